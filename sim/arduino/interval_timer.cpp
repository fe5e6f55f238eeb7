// IntervalTimer on the host: four slots, serviced from the backend's timer events.
#include "IntervalTimer.h"

#include "arduino_state.hpp"
#include "arduino_time.h"

namespace stepdance::arduino {
namespace {

constexpr int kTimers = 4;           // the Teensy 4's PIT channels
constexpr int kMaxCallsPerRun = 64;  // catch-up bound after a long stall

struct TimerSlot {
  const IntervalTimer* owner = nullptr;  // nullptr: free
  IntervalTimer::Callback callback = nullptr;
  double period_us = 0;
  double due_us = 0;  // board time in µs, unwrapped
};

TimerSlot timers[kTimers];
int running = 0;  // timers in use: the frame tick returns at once when none is
uint32_t last_micros = 0;
double elapsed_us = 0;

bool valid_period(double period_us) { return period_us >= 1.0 && period_us <= 4294967295.0; }

// Board time in µs since reset, not wrapping, as long as it is read once per 71 minutes.
double now_us() {
  const uint32_t now = micros();
  elapsed_us += static_cast<uint32_t>(now - last_micros);
  last_micros = now;
  return elapsed_us;
}

TimerSlot* slot_of(const IntervalTimer* owner) {
  for (TimerSlot& timer : timers) {
    if (timer.owner == owner) return &timer;
  }
  return nullptr;
}

}  // namespace

void run_interval_timers() {
  if (running == 0) return;
  const double now = now_us();
  for (TimerSlot& timer : timers) {
    for (int calls = 0; timer.owner != nullptr && timer.due_us <= now && calls < kMaxCallsPerRun; ++calls) {
      timer.due_us += timer.period_us;
      timer.callback();  // may end() or update() its own timer
    }
    if (timer.owner != nullptr && timer.due_us <= now) timer.due_us = now + timer.period_us;  // too far behind
  }
}

namespace internal {

void reset_interval_timer_state() {
  for (TimerSlot& timer : timers) timer = TimerSlot{};
  running = 0;
  last_micros = micros();
  elapsed_us = 0;
}

bool start_interval_timer(const IntervalTimer* owner, IntervalTimer::Callback callback, double period_us) {
  if (callback == nullptr || !valid_period(period_us)) return false;
  TimerSlot* timer = slot_of(owner);
  if (timer == nullptr) {
    timer = slot_of(nullptr);
    if (timer == nullptr) return false;
    ++running;
  }
  *timer = {owner, callback, period_us, now_us() + period_us};
  return true;
}

void update_interval_timer(const IntervalTimer* owner, double period_us) {
  TimerSlot* timer = slot_of(owner);
  if (timer != nullptr && valid_period(period_us)) timer->period_us = period_us;
}

void stop_interval_timer(const IntervalTimer* owner) {
  if (TimerSlot* timer = slot_of(owner)) {
    *timer = TimerSlot{};
    --running;
  }
}

}  // namespace internal
}  // namespace stepdance::arduino

bool IntervalTimer::begin(Callback callback, double period_us) {
  return stepdance::arduino::internal::start_interval_timer(this, callback, period_us);
}

void IntervalTimer::update(double period_us) { stepdance::arduino::internal::update_interval_timer(this, period_us); }

void IntervalTimer::end() { stepdance::arduino::internal::stop_interval_timer(this); }
