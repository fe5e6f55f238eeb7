// Interrupt plumbing: NVIC registers (ARMv7-M ARM §B3.4), PRIMASK critical sections (§B1.4.3).
#if defined(__IMXRT1062__)

#include "stepdance/platform/teensy/irq.hpp"

#include "stepdance/hal/hal.hpp"
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

bool in_thread_mode() {
  uint32_t ipsr;
  __asm__ volatile("mrs %0, ipsr" : "=r"(ipsr));
  return (ipsr & 0x1FFu) == 0;
}

}  // namespace stepdance::platform::teensy::irq

namespace stepdance::hal {

uint32_t irq_save() {
  uint32_t primask;
  __asm__ volatile("mrs %0, primask\n\tcpsid i" : "=r"(primask)::"memory");
  return primask;
}

void irq_restore(uint32_t state) { __asm__ volatile("msr primask, %0" ::"r"(state) : "memory"); }

}  // namespace stepdance::hal

#endif  // __IMXRT1062__
