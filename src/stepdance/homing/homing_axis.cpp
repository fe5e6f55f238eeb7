// HomingAxis: the per-axis homing routine, one frame at a time.
#include "stepdance/homing/homing_axis.hpp"

#include <math.h>

#include "stepdance/core/fault.hpp"
#include "stepdance/hal/hal.hpp"

namespace stepdance {
namespace {}  // namespace

// Only the sign of direction counts (toward the switch), and velocity is a speed in world units/s.
void HomingAxis::configure(uint8_t limit_pin, double value_at_limit, float direction, float velocity,
                           BlockPort* target) {
  pin_ = limit_pin;
  value_at_limit_ = value_at_limit;
  direction_ = direction < 0 ? -1.0 : 1.0;
  fast_velocity_ = fabs(static_cast<double>(velocity));
  target_ = target;
  set_debounce_ms(debounce_ms_);
}

// An active-low switch (wired to ground) gets a pull-up, an active-high one (wired to 3.3 V) a
// pull-down, so an open switch reads inactive either way. The output is
// incremental so homing adds motion to the target instead of overwriting its position. Pre-channel
// stage: the move reaches the channel in the same frame.
Status HomingAxis::begin() {
  const Status pin = hal::gpio_mode(pin_, active_low_ ? hal::PinMode::kInputPullup : hal::PinMode::kInputPulldown);
  if (pin != Status::kOk) return pin;
  output.begin(&position_, BLOCKPORT_OUTPUT, this);
  if (target_ != nullptr) output.map(target_, INCREMENTAL);
  switch_.restart(read_switch(), position_);
  return register_in(Stage::kPreChannel);
}

// Debounce in frames, rounded, at least one: the switch is sampled once per frame.
void HomingAxis::set_debounce_ms(double ms) {
  debounce_ms_ = ms;
  const double frames = ms * 1000.0 / frame_period_us();
  switch_.set_stable_samples(frames < 1.0 ? 1u : static_cast<uint32_t>(frames + 0.5));
}

void HomingAxis::start() {
  frames_ = 0;
  // Frames follow the period chosen before dance_start(); the times set in ms stay the same.
  set_debounce_ms(debounce_ms_);
  timeout_frames_ = timeout_ms_ * (1000u / frame_period_us());
  state_ = HOMING_AXIS_STATE_BEGIN;
}

void HomingAxis::abort() { state_ = HOMING_AXIS_STATE_WAITING; }

bool HomingAxis::read_switch() const { return hal::gpio_read(pin_) != active_low_; }

// Frame context. The switch is sampled every frame, even idle, so the debouncer's record of where the
// last change happened (value_at_change) is current when the approach trips it. The timeout covers
// the whole routine.
void HomingAxis::run() {
  switch_.sample(read_switch(), position_);
  const uint8_t state = state_;
  const bool idle = state == HOMING_AXIS_STATE_WAITING || state == HOMING_AXIS_STATE_FINISHED ||
                    state == HOMING_AXIS_STATE_FAILED || state == HOMING_AXIS_STATE_CENTERING;
  if (!idle) {
    ++frames_;
    if (timeout_frames_ != 0 && frames_ > timeout_frames_) {
      fail("homing timed out");
    } else {
      run_state(switch_.level(), !switch_.level());
    }
  }
  output.push();
}

// The routine (as Grbl's homing cycle): back off if already on the switch, seek it fast, pull off,
// approach again slowly for a repeatable trip point, then pull off a last time so the machine
// does not rest on the switch. The slow speed defaults to a tenth of the fast one.
void HomingAxis::run_state(bool active, bool released) {
  const double slow = slow_velocity_ > 0 ? slow_velocity_ : fast_velocity_ / 10.0;
  switch (state_) {
    case HOMING_AXIS_STATE_BEGIN: enter(active ? HOMING_AXIS_STATE_BACKING_OFF : HOMING_AXIS_STATE_SEEKING); break;
    case HOMING_AXIS_STATE_BACKING_OFF:
      if (released)
        enter(HOMING_AXIS_STATE_SEEKING);
      else
        move(-direction_ * fast_velocity_);
      break;
    case HOMING_AXIS_STATE_SEEKING:
      if (active)
        enter(HOMING_AXIS_STATE_PULLING_OFF);
      else if (!move(direction_ * fast_velocity_))
        fail("homing: no switch within the maximum travel");
      break;
    case HOMING_AXIS_STATE_PULLING_OFF:
      if (pull_off_done(released))
        enter(HOMING_AXIS_STATE_APPROACHING);
      else
        move(-direction_ * fast_velocity_);
      break;
    case HOMING_AXIS_STATE_APPROACHING:
      if (active) {
        trip_position_ = switch_.value_at_change();
        enter(HOMING_AXIS_STATE_FINAL_PULL_OFF);
      } else if (!move(direction_ * slow)) {
        fail("homing: no switch within the maximum travel");
      }
      break;
    case HOMING_AXIS_STATE_FINAL_PULL_OFF:
      if (pull_off_done(released))
        enter(HOMING_AXIS_STATE_FINISHED);
      else
        move(-direction_ * slow);
      break;
    default: break;
  }
}

// Moves one frame at `velocity`; a pull-off lands exactly on its distance. False when a seek or
// approach has gone farther than the maximum travel.
// Frame context; velocity in world units/s, one frame's worth per call.
bool HomingAxis::move(double velocity) {
  double step = velocity * frame_period_s();
  const double moved = fabs(position_ - phase_start_);
  const bool pulling = state_ == HOMING_AXIS_STATE_PULLING_OFF || state_ == HOMING_AXIS_STATE_FINAL_PULL_OFF;
  if (pulling && moved < pull_off_ && fabs(step) > pull_off_ - moved)
    step = step > 0 ? pull_off_ - moved : moved - pull_off_;
  output.set(position_ + step);  // moves position_ (the port's target) and records the change
  return max_travel_ <= 0 || pulling || fabs(position_ - phase_start_) <= max_travel_;
}

// Both conditions: clear of the switch and the full pull-off distance (with a relative tolerance for
// floating-point sums of per-frame steps).
bool HomingAxis::pull_off_done(bool released) {
  return released && fabs(position_ - phase_start_) >= pull_off_ * (1 - 1e-12);
}

void HomingAxis::enter(uint8_t state) {
  phase_start_ = position_;
  state_ = state;
}

// An alarm, not a fatal fault: the machine stays usable and the sketch can retry after fixing it.
void HomingAxis::fail(const char* detail) {
  state_ = HOMING_AXIS_STATE_FAILED;
  report_fault(FaultLevel::kAlarm, FaultReason::kTimeout, "homing", detail);
}

}  // namespace stepdance
