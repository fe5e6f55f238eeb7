// The frame timer: FlexIO3's hardware frame clock, the tick ISR and the frame ISR.
//
//   tick k (hardware) ─► all claimed ports start shifting the words in their buffers
//        └► tick ISR (priority 16): zero the buffers, count the tick, pend the frame ISR
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
//  - Never sent late. The commit runs with interrupts off, waits until any tick that preceded the
//    buffer writes has raised its flag, and checks it: if a tick came first, the words are zeroed
//    and counted in FrameDiagnostics::late_frames (dropped, as the slot has passed).
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

void tick_isr() {
  flexio::clear_tick_flag();
  output_ports_disarm();
  tick_count = tick_count + 1;
  irq::pend(kFrameIrq);
}

// Writes the frame's words for the next tick, or drops them if that tick has already passed.
void commit_frame(uint32_t epoch) {
  const uint32_t state = hal::irq_save();
  const uint8_t written = output_ports_commit_staged();
  flexio::settle_writes();
  const bool late = flexio::tick_flag() || tick_count != epoch;
  if (late && written != 0) {
    output_ports_zero(written);
    late_frames = late_frames + 1;
  }
  hal::irq_restore(state);
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
  const Status started = teensy::flexio::start_frame_clock(period_us);
  if (started != Status::kOk) {
    teensy::frame_timer_stop();
    return started;
  }
  // Fail loudly rather than run without frames: the first tick must arrive within a few periods.
  const uint32_t ticks_before = teensy::tick_count;
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
