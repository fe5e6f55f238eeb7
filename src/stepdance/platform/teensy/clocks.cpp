// Time and clock rates: micros, the DWT cycle counter, bus and PERCLK frequencies.
#if defined(__IMXRT1062__)

#include "stepdance/platform/teensy/clocks.hpp"

#include "stepdance/hal/hal.hpp"
#include "stepdance/platform/teensy/regs_ccm.hpp"
#include "stepdance/platform/teensy/regs_dwt.hpp"
#include "stepdance/platform/teensy/teensyduino_services.hpp"

namespace stepdance::platform::teensy {
namespace {

namespace dwt = regs::dwt;

// Starts the DWT cycle counter (Teensyduino's startup usually has already; doing it again is
// harmless). ARMv7-M ARM §C1.6.5 (TRCENA), §C1.8.7 (CYCCNTENA).
bool start_cycle_counter() {
  dwt::demcr() |= dwt::kDemcrTraceEnable;
  dwt::lar() = dwt::kLarUnlockKey;
  dwt::ctrl() |= dwt::kCtrlCycleCounterEnable;
  return true;
}

// Runs during static initialisation, before setup(), so cycles_now() counts from the start.
[[maybe_unused]] const bool cycle_counter_started = start_cycle_counter();

}  // namespace

uint32_t bus_clock_hz() { return services::bus_clock_hz(); }

uint32_t perclk_hz() {
  namespace ccm = regs::ccm;
  const uint32_t cscmr1 = ccm::cscmr1();
  const uint32_t source = (cscmr1 & ccm::kCscmr1PerclkSelOsc) ? ccm::kOscillatorHz : bus_clock_hz();
  return source / ((cscmr1 & ccm::kCscmr1PerclkPodfMask) + 1u);
}

}  // namespace stepdance::platform::teensy

namespace stepdance::hal {

uint32_t micros_now() { return platform::teensy::services::micros_since_boot(); }

uint32_t cycles_now() { return platform::teensy::regs::dwt::cyccnt(); }

uint32_t cycles_per_second() { return platform::teensy::services::core_clock_hz(); }

}  // namespace stepdance::hal

#endif  // __IMXRT1062__
