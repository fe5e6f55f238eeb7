// Register access helpers shared by the register headers of the Teensy 4.x (i.MX RT1062) backend.
//
// Every regs_*.hpp file defines only the registers this backend programs, as constexpr addresses
// plus small inline accessors, each with the reference-manual section it comes from. "RM" means
// the i.MX RT1060 Processor Reference Manual; "ARMv7-M ARM" the ARMv7-M Architecture Reference
// Manual. Names are kCamelCase or lower_case on purpose: Teensyduino's imxrt.h defines upper-case
// macros for the same registers, and those must never collide with ours.
#pragma once

#if defined(__IMXRT1062__)

#include <stdint.h>

namespace stepdance::platform::teensy::regs {

/// A 32-bit memory-mapped register at `address`.
inline volatile uint32_t& reg32(uint32_t address) { return *reinterpret_cast<volatile uint32_t*>(address); }
/// A 16-bit memory-mapped register at `address`.
inline volatile uint16_t& reg16(uint32_t address) { return *reinterpret_cast<volatile uint16_t*>(address); }
/// An 8-bit memory-mapped register at `address`.
inline volatile uint8_t& reg8(uint32_t address) { return *reinterpret_cast<volatile uint8_t*>(address); }

/// A field value `value` placed at bit `shift`.
constexpr uint32_t field(uint32_t value, unsigned shift) { return value << shift; }

/// Waits until every earlier memory access has completed (ARMv7-M ARM §A3.8.3, DSB).
inline void data_sync_barrier() { __asm__ volatile("dsb" ::: "memory"); }

}  // namespace stepdance::platform::teensy::regs

#endif  // __IMXRT1062__
