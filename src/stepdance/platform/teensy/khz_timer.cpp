// The kilohertz timer on GPT2 (RM chapter 52), a separate vector below the frame ISR's priority.
#if defined(__IMXRT1062__)

#include "stepdance/hal/hal.hpp"
#include "stepdance/platform/teensy/clocks.hpp"
#include "stepdance/platform/teensy/irq.hpp"
#include "stepdance/platform/teensy/regs_ccm.hpp"
#include "stepdance/platform/teensy/regs_gpt.hpp"
#include "stepdance/platform/teensy/regs_nvic.hpp"
#include "stepdance/platform/teensy/timers.hpp"

namespace stepdance::platform::teensy {
namespace {

namespace gpt = regs::gpt2;
namespace ccm = regs::ccm;

hal::Isr volatile tick_handler = nullptr;

void gpt2_isr() {
  gpt::sr() = gpt::kSrCompare1;
  regs::data_sync_barrier();  // the flag must be clear before the exception returns
  const hal::Isr handler = tick_handler;
  if (handler != nullptr) handler();
}

// GPT2 in restart mode on PERCLK: the counter restarts after OCR1, raising OF1 once per period.
Status start_gpt2(uint32_t period_ticks) {
  ccm::gate_on(ccm::kGateGpt2Bus);
  ccm::gate_on(ccm::kGateGpt2Serial);
  gpt::cr() = 0;
  gpt::ir() = 0;
  gpt::cr() = gpt::kCrSoftwareReset;
  for (uint32_t spins = 0; gpt::cr() & gpt::kCrSoftwareReset; ++spins) {
    if (spins > 100000u) return Status::kUnsupported;
  }
  gpt::pr() = 0;
  gpt::ocr1() = period_ticks - 1u;
  gpt::sr() = gpt::kSrAllFlags;
  gpt::cr() = gpt::cr_clock_source(1) | gpt::kCrEnableResets;
  gpt::ir() = gpt::kSrCompare1;  // OF1IE has OF1's bit position
  gpt::cr() |= gpt::kCrEnable;
  return Status::kOk;
}

}  // namespace

void khz_timer_stop() {
  if (ccm::gate_is_on(ccm::kGateGpt2Bus) && ccm::gate_is_on(ccm::kGateGpt2Serial)) {
    gpt::cr() = 0;
    gpt::ir() = 0;
  }
  irq::disable(regs::nvic::kIrqGpt2);
  tick_handler = nullptr;
}

}  // namespace stepdance::platform::teensy

namespace stepdance::hal {

namespace teensy = platform::teensy;

Status khz_timer_start(uint32_t period_us, Isr on_tick) {
  if (on_tick == nullptr || period_us == 0) return Status::kBadArgument;
  // 32-bit arithmetic only (PERCLK is a whole number of kHz): ticks = PERCLK × period.
  const uint32_t ticks_per_ms = teensy::perclk_hz() / 1000u;
  if (ticks_per_ms == 0 || period_us > 0xFFFFFFFFu / ticks_per_ms) return Status::kBadArgument;
  const uint32_t ticks = ticks_per_ms * period_us / 1000u;
  if (ticks < 2u) return Status::kBadArgument;
  teensy::khz_timer_stop();
  teensy::tick_handler = on_tick;
  teensy::irq::install(teensy::regs::nvic::kIrqGpt2, &teensy::gpt2_isr, teensy::irq::kKilohertzPriority);
  const Status started = teensy::start_gpt2(ticks);
  if (started != Status::kOk) teensy::khz_timer_stop();
  return started;
}

}  // namespace stepdance::hal

#endif  // __IMXRT1062__
