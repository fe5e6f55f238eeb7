// Interrupt plumbing: NVIC registers (ARMv7-M ARM §B3.4), PRIMASK critical sections and BASEPRI
// priority masking (§B1.4.3).
#if defined(__IMXRT1062__)

#include "stepdance/platform/teensy/irq.hpp"

#include "stepdance/hal/hal.hpp"
#include "stepdance/platform/teensy/regs_core.hpp"
#include "stepdance/platform/teensy/regs_nvic.hpp"
#include "stepdance/platform/teensy/teensyduino_services.hpp"

namespace stepdance::platform::teensy::irq {

namespace nvic = regs::nvic;

void install(uint8_t irq, void (*handler)(), uint8_t priority) {
  nvic::icer(irq) = nvic::irq_bit(irq);
  regs::data_sync_barrier();
  services::set_vector(irq, handler);
  nvic::ipr(irq) = priority;
  nvic::icpr(irq) = nvic::irq_bit(irq);
  nvic::iser(irq) = nvic::irq_bit(irq);
}

void disable(uint8_t irq) {
  nvic::icer(irq) = nvic::irq_bit(irq);
  nvic::icpr(irq) = nvic::irq_bit(irq);
  regs::data_sync_barrier();
}

void pend(uint8_t irq) { nvic::ispr(irq) = nvic::irq_bit(irq); }

bool in_thread_mode() { return (regs::core::ipsr() & 0x1FFu) == 0; }

uint32_t mask_from(uint8_t priority) {
  const uint32_t previous = regs::core::basepri();
  regs::core::raise_basepri(priority);
  return previous;
}

void unmask(uint32_t previous) { regs::core::set_basepri(previous); }

}  // namespace stepdance::platform::teensy::irq

namespace stepdance::hal {

uint32_t irq_save() {
  const uint32_t primask = platform::teensy::regs::core::primask();
  platform::teensy::regs::core::disable_irqs();
  return primask;
}

void irq_restore(uint32_t state) { platform::teensy::regs::core::set_primask(state); }

}  // namespace stepdance::hal

#endif  // __IMXRT1062__
