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

#if defined(STEPDANCE_TEENSY_REGISTER_MODEL)
// Host tests only (tests/platform/teensy): every register access goes through a fake memory map
// that records it and lets the test play the hardware. Never defined in a target build.
namespace stepdance::platform::teensy::register_model {
/// Reads `bytes` (1, 2 or 4) at `address` from the model.
uint32_t read(uint32_t address, unsigned bytes);
/// Writes `bytes` (1, 2 or 4) at `address` into the model.
void write(uint32_t address, unsigned bytes, uint32_t value);
/// A DSB: the model records it.
void barrier();
/// The ARMv7-M special registers PRIMASK and BASEPRI, and IPSR (read only), in the model.
uint32_t read_special(const char* name);
void write_special(const char* name, uint32_t value);

/// A register as the backend uses it: read by conversion, written by assignment.
template <typename T>
class Register {
 public:
  explicit Register(uint32_t address) : address_(address) {}
  operator T() const { return static_cast<T>(read(address_, sizeof(T))); }
  const Register& operator=(uint32_t value) const {
    write(address_, sizeof(T), static_cast<T>(value));
    return *this;
  }
  const Register& operator=(const Register& other) const {
    return *this = static_cast<uint32_t>(static_cast<T>(other));
  }
  const Register& operator|=(uint32_t bits) const { return *this = static_cast<T>(*this) | bits; }
  const Register& operator&=(uint32_t bits) const { return *this = static_cast<T>(*this) & bits; }

 private:
  uint32_t address_;
};
}  // namespace stepdance::platform::teensy::register_model
#endif

namespace stepdance::platform::teensy::regs {

#if defined(STEPDANCE_TEENSY_REGISTER_MODEL)
using Reg32 = register_model::Register<uint32_t>;
using Reg16 = register_model::Register<uint16_t>;
using Reg8 = register_model::Register<uint8_t>;
inline Reg32 reg32(uint32_t address) { return Reg32(address); }
inline Reg16 reg16(uint32_t address) { return Reg16(address); }
inline Reg8 reg8(uint32_t address) { return Reg8(address); }
inline void data_sync_barrier() { register_model::barrier(); }
#else
/// A reference to a 32-, 16- or 8-bit memory-mapped register.
using Reg32 = volatile uint32_t&;
using Reg16 = volatile uint16_t&;
using Reg8 = volatile uint8_t&;
/// A 32-bit memory-mapped register at `address`.
inline Reg32 reg32(uint32_t address) { return *reinterpret_cast<volatile uint32_t*>(address); }
/// A 16-bit memory-mapped register at `address`.
inline Reg16 reg16(uint32_t address) { return *reinterpret_cast<volatile uint16_t*>(address); }
/// An 8-bit memory-mapped register at `address`.
inline Reg8 reg8(uint32_t address) { return *reinterpret_cast<volatile uint8_t*>(address); }
/// Waits until every earlier memory access has completed (ARMv7-M ARM §A3.8.3, DSB).
inline void data_sync_barrier() { __asm__ volatile("dsb" ::: "memory"); }
#endif

/// A field value `value` placed at bit `shift`.
constexpr uint32_t field(uint32_t value, unsigned shift) { return value << shift; }

}  // namespace stepdance::platform::teensy::regs

#endif  // __IMXRT1062__
