// The input sample clock: PIT channel 3, phase-locked to the frame clock, pulses the ENC TRIGGER
// inputs through XBAR1 a fixed lead before every frame tick (RM chapters 53, 61 and 56).
//
// Why: the frame ISR reads the quadrature counters a few hundred nanoseconds after its tick, and
// how many depends on the instruction the tick interrupts. A knob edge inside that window is seen
// in this frame or the next by chance. Latched by hardware, every frame sees the counts of one
// instant, the same distance before each tick, whatever the interrupt latency; and the
// simulator's host boards can model that instant exactly (docs/simulator.md, "Image boards").
//
// Phase lock: PERCLK (24 MHz from the crystal) and FlexIO3's clock both come from the 24 MHz
// crystal, so a PIT period of exactly one frame never drifts from the frame clock. The channel is
// started from the first tick ISR after the frame clock starts, with a first period one lead
// shorter than a frame, so each expiry comes kLeadUs (plus the tick ISR's entry latency, fixed
// once the channel runs) before a tick. The frame ISR then reads the hold registers: the sample
// is always complete before the frame reads it.
//
// Channel 3: Teensyduino's IntervalTimer takes the first channel whose TCTRL is 0, so it skips
// ours while we run; if a sketch holds channel 3 already, the counters are read live instead and
// the log says so.
#if defined(__IMXRT1062__)

#include "stepdance/hal/hal.hpp"
#include "stepdance/platform/teensy/clocks.hpp"
#include "stepdance/platform/teensy/regs_ccm.hpp"
#include "stepdance/platform/teensy/regs_pit.hpp"
#include "stepdance/platform/teensy/timers.hpp"

namespace stepdance::platform::teensy {
namespace {

namespace pit = regs::pit;

constexpr uint32_t kLeadUs = 2;  // the sample comes this long before the tick it is read after

volatile bool armed = false;     // start the channel at the next tick
volatile bool claimed = false;   // the channel is ours (running or armed)
volatile bool sampling = false;  // it has expired once: the hold registers carry a sample
uint32_t period_ticks = 0;       // PERCLK ticks per frame
uint32_t lead_ticks = 0;         // PERCLK ticks in kLeadUs

}  // namespace

bool sample_clock_arm(uint32_t period_us) {
  const uint32_t hz = perclk_hz();
  if (hz % 1000000u != 0) {
    hal::log_message("sample clock: PERCLK is not a whole number of MHz; encoders are read live");
    return false;
  }
  if (period_us <= kLeadUs) {
    hal::log_message("sample clock: the frame is shorter than the sample lead; encoders are read live");
    return false;
  }
  regs::ccm::gate_on(regs::ccm::kGatePit);
  pit::mcr() &= ~pit::kMcrModuleDisable;
  if (!claimed && (pit::tctrl(kSampleClockPitChannel) & pit::kTctrlEnable)) {
    hal::log_message("sample clock: PIT channel 3 is in use; encoders are read live");
    return false;
  }
  pit::tctrl(kSampleClockPitChannel) = 0;
  pit::tflg(kSampleClockPitChannel) = pit::kTflgExpired;
  period_ticks = period_us * (hz / 1000000u);
  lead_ticks = kLeadUs * (hz / 1000000u);
  sampling = false;
  claimed = true;
  armed = true;
  return true;
}

void sample_clock_on_tick() {
  if (!armed) return;
  armed = false;
  pit::ldval(kSampleClockPitChannel) = period_ticks - lead_ticks - 1u;
  pit::tctrl(kSampleClockPitChannel) = pit::kTctrlEnable;
  pit::ldval(kSampleClockPitChannel) = period_ticks - 1u;  // from the first expiry on: one frame
}

bool sample_clock_sampled() {
  if (sampling) return true;
  if (!claimed || armed || !(pit::tflg(kSampleClockPitChannel) & pit::kTflgExpired)) return false;
  sampling = true;
  return true;
}

void sample_clock_stop() {
  if (!claimed) return;
  armed = false;
  sampling = false;
  pit::tctrl(kSampleClockPitChannel) = 0;
  pit::tflg(kSampleClockPitChannel) = pit::kTflgExpired;
  claimed = false;
}

}  // namespace stepdance::platform::teensy

#endif  // __IMXRT1062__
