// The ARMv7-M special registers the backend touches: PRIMASK, BASEPRI and IPSR
// (ARMv7-M ARM §B1.4.3 "the special-purpose mask registers", §B5.2.3 MRS/MSR).
//
// PRIMASK = 1 masks every configurable-priority exception. BASEPRI = n (n ≠ 0) masks exceptions
// whose priority number is n or more (less urgent), so exceptions above n keep running;
// BASEPRI_MAX writes only when that raises the masking level. The RT1062 implements the top
// 4 priority bits, so n is a multiple of 16.
#pragma once

#if defined(__IMXRT1062__)

#include <stdint.h>

#include "stepdance/platform/teensy/regs_common.hpp"

namespace stepdance::platform::teensy::regs::core {

#if defined(STEPDANCE_TEENSY_REGISTER_MODEL)
inline uint32_t primask() { return register_model::read_special("primask"); }
inline void set_primask(uint32_t value) { register_model::write_special("primask", value); }
inline void disable_irqs() { register_model::write_special("primask", 1); }
inline uint32_t basepri() { return register_model::read_special("basepri"); }
inline void set_basepri(uint32_t value) { register_model::write_special("basepri", value); }
inline void raise_basepri(uint32_t value) {
  const uint32_t now = basepri();
  if (value != 0 && (now == 0 || value < now)) set_basepri(value);
}
inline uint32_t ipsr() { return register_model::read_special("ipsr"); }
#else
/// PRIMASK (bit 0: 1 = interrupts masked).
inline uint32_t primask() {
  uint32_t value;
  __asm__ volatile("mrs %0, primask" : "=r"(value)::"memory");
  return value;
}
inline void set_primask(uint32_t value) { __asm__ volatile("msr primask, %0" ::"r"(value) : "memory"); }
/// CPSID i: PRIMASK = 1.
inline void disable_irqs() { __asm__ volatile("cpsid i" ::: "memory"); }
/// BASEPRI (0 = no masking).
inline uint32_t basepri() {
  uint32_t value;
  __asm__ volatile("mrs %0, basepri" : "=r"(value)::"memory");
  return value;
}
inline void set_basepri(uint32_t value) { __asm__ volatile("msr basepri, %0" ::"r"(value) : "memory"); }
/// BASEPRI_MAX: raises the masking level to `value`, never lowers it. The ISB makes the new level
/// apply to the next instruction (ARMv7-M ARM §B5.2.3).
inline void raise_basepri(uint32_t value) { __asm__ volatile("msr basepri_max, %0\n\tisb" ::"r"(value) : "memory"); }
/// IPSR: the number of the exception being handled, 0 in thread mode.
inline uint32_t ipsr() {
  uint32_t value;
  __asm__ volatile("mrs %0, ipsr" : "=r"(value));
  return value;
}
#endif

}  // namespace stepdance::platform::teensy::regs::core

#endif  // __IMXRT1062__
