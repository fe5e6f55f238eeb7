// NVIC: enable, pend and prioritise interrupts (ARMv7-M ARM §B3.4), and the interrupt numbers of
// the peripherals we use (RM chapter 4, CM7 interrupt table).
#pragma once

#if defined(__IMXRT1062__)

#include <stdint.h>

#include "stepdance/platform/teensy/regs_common.hpp"

namespace stepdance::platform::teensy::regs::nvic {

/// ISERn: set-enable, one bit per interrupt. ARMv7-M ARM §B3.4.4, NVIC_ISER.
inline Reg32 iser(unsigned irq) { return reg32(0xE000E100u + 4u * (irq / 32u)); }
/// ICERn: clear-enable. ARMv7-M ARM §B3.4.5, NVIC_ICER.
inline Reg32 icer(unsigned irq) { return reg32(0xE000E180u + 4u * (irq / 32u)); }
/// ISPRn: set-pending. ARMv7-M ARM §B3.4.6, NVIC_ISPR.
inline Reg32 ispr(unsigned irq) { return reg32(0xE000E200u + 4u * (irq / 32u)); }
/// ICPRn: clear-pending. ARMv7-M ARM §B3.4.7, NVIC_ICPR.
inline Reg32 icpr(unsigned irq) { return reg32(0xE000E280u + 4u * (irq / 32u)); }
/// IPRn: one priority byte per interrupt; the RT1062 implements the top 4 bits (16 levels).
/// ARMv7-M ARM §B3.4.9, NVIC_IPR.
inline Reg8 ipr(unsigned irq) { return reg8(0xE000E400u + irq); }
/// Bit of an interrupt in its ISER/ICER/ISPR/ICPR word.
constexpr uint32_t irq_bit(unsigned irq) { return 1u << (irq % 32u); }

// Interrupt numbers (RM chapter 4, CM7 domain interrupt summary).
constexpr uint8_t kIrqAdc1 = 67;
constexpr uint8_t kIrqAdc2 = 68;
constexpr uint8_t kIrqGpt2 = 101;
constexpr uint8_t kIrqFlexpwm1Sm3 = 105;
constexpr uint8_t kIrqFlexpwm2Sm0 = 137;
constexpr uint8_t kIrqFlexpwm2Sm1 = 138;
constexpr uint8_t kIrqFlexpwm2Sm2 = 139;
/// A reserved line with no peripheral behind it: pended by software to run the frame stages.
constexpr uint8_t kIrqReservedForFrame = 155;
constexpr uint8_t kIrqFlexio3 = 156;

}  // namespace stepdance::platform::teensy::regs::nvic

#endif  // __IMXRT1062__
