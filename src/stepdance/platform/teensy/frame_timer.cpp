// The frame timer: FlexIO3's hardware frame clock, the tick ISR and the frame ISR.
//
//   tick k (hardware) ─► all claimed ports start shifting the words in their buffers
//        └► tick ISR (priority 16): zero the buffers, count the tick, pend the frame ISR (the
//           first one after a start also starts the input sample clock: sample_clock.cpp)
//             └► frame ISR (priority 48): run the frame stages, then commit the staged words
//                  (launched by the hardware at tick k+1)
//
// Guarantees, and why they hold:
//  - Fixed phase. A frame starts on the frame clock's rising edge, in hardware, for all four ports
//    at once (one trigger, synchronised in the FlexIO clock domain: < 20 ns, no software on the
//    path). ISR latency and frame-ISR load only decide whether the words are there in time.
//  - Never closer than the frame period. Launches happen only on rising edges of one free-running
//    timer, exactly one period apart; a transmission lasts 32 µs and the period is longer.
//  - Never sent twice. Shifters reload their buffer at every launch, so the tick ISR zeroes the
//    buffers right after each launch (its flag is raised 4 FlexIO clocks after the same edge, so
//    the launch has always happened). It runs above the frame ISR, so an overrunning frame cannot
//    hold it back.
//  - Never sent late, and all ports or none. The commit masks the tick ISR and everything below it
//    (BASEPRI, so the capture ISRs at priority 0 keep running). It first checks whether the tick
//    has already come or is less than the commit guard away: then it writes no port at all and
//    counts the frame in FrameDiagnostics::late_frames. Otherwise it writes every staged port,
//    well inside the guard, and checks again; a tick that still slipped in (captures preempting
//    the writes for longer than the guard) zeroes every written port and counts it too.
//  - Exact restart. A start after a stop waits until one full period has passed since the stop, so
//    the previous run's last transmission has ended (every port timer is idle and takes the first
//    new tick) and no two launches are ever closer than the period.
#if defined(__IMXRT1062__)

#include "stepdance/hal/hal.hpp"
#include "stepdance/platform/teensy/flexio3.hpp"
#include "stepdance/platform/teensy/frame_diagnostics.hpp"
#include "stepdance/platform/teensy/irq.hpp"
#include "stepdance/platform/teensy/output_ports.hpp"
#include "stepdance/platform/teensy/regs_nvic.hpp"
#include "stepdance/platform/teensy/timers.hpp"

namespace stepdance::platform::teensy {
namespace {

constexpr uint8_t kTickIrq = regs::nvic::kIrqFlexio3;
constexpr uint8_t kFrameIrq = regs::nvic::kIrqReservedForFrame;

hal::Isr volatile frame_handler = nullptr;
volatile bool running = false;
volatile uint32_t tick_count = 0;
volatile uint32_t frame_epoch = 0;  // tick_count when the current frame ISR began
volatile uint32_t frame_count = 0;
volatile uint32_t ticks_without_frame = 0;
volatile uint32_t late_frames = 0;
volatile bool stopped_once = false;
volatile uint32_t stopped_at_cycles = 0;  // DWT cycles at the last frame_timer_stop()

void tick_isr() {
  flexio::clear_tick_flag();
  output_ports_disarm();
  sample_clock_on_tick();
  tick_count = tick_count + 1;
  irq::pend(kFrameIrq);
}

// True if the tick this frame is due for has come since the frame ISR began (or, with
// `with_guard`, is too close to start writing).
bool slot_passed(uint32_t epoch, bool with_guard) {
  return flexio::tick_flag() || tick_count != epoch || (with_guard && flexio::guard_flag());
}

// Writes the frame's words on every port for the next tick, or on none if that tick is too close
// or has passed. BASEPRI at the tick priority: the tick ISR (which zeroes the buffers and bumps
// tick_count) cannot run between the check and the writes; the capture ISRs still can.
void commit_frame(uint32_t epoch) {
  const uint32_t mask = irq::mask_from(irq::kTickPriority);
  if (slot_passed(epoch, true)) {
    output_ports_drop_staged();
    late_frames = late_frames + 1;
  } else {
    const uint8_t written = output_ports_commit_staged();
    flexio::settle_writes();
    if (slot_passed(epoch, false)) {
      output_ports_zero(written);
      late_frames = late_frames + 1;
    }
  }
  irq::unmask(mask);
}

// After a stop, waits until a full period has passed: the last launch is then over and at least a
// period away from the first new one.
void wait_after_stop(uint32_t period_us) {
  if (!stopped_once) return;
  const uint32_t cycles_per_us = hal::cycles_per_second() / 1000000u;
  while (hal::cycles_now() - stopped_at_cycles < period_us * cycles_per_us) {
  }
}

void frame_isr() {
  const uint32_t epoch = tick_count;
  if (epoch - frame_epoch > 1u) ticks_without_frame = ticks_without_frame + (epoch - frame_epoch - 1u);
  frame_epoch = epoch;
  const hal::Isr handler = frame_handler;
  if (handler != nullptr) handler();
  if (running) commit_frame(epoch);  // a fault inside the frame stops the timers
  frame_count = frame_count + 1;
}

}  // namespace

void frame_timer_stop() {
  flexio::stop_frame_clock();
  sample_clock_stop();
  stopped_at_cycles = hal::cycles_now();
  stopped_once = true;
  irq::disable(kTickIrq);
  irq::disable(kFrameIrq);
  running = false;
  frame_handler = nullptr;
}

FrameDiagnostics frame_diagnostics() {
  return FrameDiagnostics{tick_count, frame_count, ticks_without_frame, late_frames};
}

}  // namespace stepdance::platform::teensy

namespace stepdance::hal {

namespace teensy = platform::teensy;

Status frame_timer_start(uint32_t period_us, Isr on_frame) {
  if (on_frame == nullptr) return Status::kBadArgument;
  if (teensy::running) return Status::kBusy;
  teensy::flexio::power_up();
  teensy::output_ports_disarm();       // nothing staged before the start may go out
  teensy::output_ports_attach_pins();  // back from a safe state, if there was one
  teensy::frame_handler = on_frame;
  teensy::frame_epoch = teensy::tick_count;
  teensy::irq::install(teensy::kFrameIrq, &teensy::frame_isr, teensy::irq::kFramePriority);
  teensy::irq::install(teensy::kTickIrq, &teensy::tick_isr, teensy::irq::kTickPriority);
  teensy::running = true;
  teensy::wait_after_stop(period_us);
  teensy::sample_clock_arm(period_us);               // if it cannot, the encoders are read live
  const uint32_t ticks_before = teensy::tick_count;  // read first: the first tick comes at once
  const Status started = teensy::flexio::start_frame_clock(period_us);
  if (started != Status::kOk) {
    teensy::frame_timer_stop();
    return started;
  }
  // Fail loudly rather than run without frames: the first tick must arrive within a few periods.
  const uint32_t waited_from = micros_now();
  while (teensy::tick_count == ticks_before) {
    if (micros_now() - waited_from > 3u * period_us + 10u) {
      teensy::frame_timer_stop();
      log_message("frame_timer_start: the FlexIO3 frame clock does not tick");
      return Status::kUnsupported;
    }
  }
  return Status::kOk;
}

void timers_stop() {
  teensy::frame_timer_stop();
  teensy::khz_timer_stop();
}

}  // namespace stepdance::hal

#endif  // __IMXRT1062__
