// ENC1/ENC2 quadrature decoders. RM chapter 56 (ENC), memory map §56.8. Registers are 16 bits.
#pragma once

#if defined(__IMXRT1062__)

#include <stdint.h>

#include "stepdance/platform/teensy/regs_common.hpp"

namespace stepdance::platform::teensy::regs::enc {

/// Base of ENC1 (index 0) or ENC2 (index 1). RM §56.8.
constexpr uint32_t base(unsigned index) { return 0x403C8000u + 0x4000u * index; }

/// CTRL: control; SWIP (bit 11) loads UINIT/LINIT into the position counter. RM §56.8, ENC_CTRL.
inline Reg16 ctrl(unsigned index) { return reg16(base(index) + 0x00u); }
constexpr uint16_t kCtrlSoftwareInitPosition = 1u << 11;
/// FILT: input filter, FILT_CNT bits 10:8 (samples = n + 3), FILT_PER bits 7:0 (IPG clocks
/// between samples, 0 = bypass). RM §56.8, ENC_FILT.
inline Reg16 filt(unsigned index) { return reg16(base(index) + 0x02u); }
constexpr uint16_t filter(uint16_t count, uint16_t period) {
  return static_cast<uint16_t>(((count & 7u) << 8) | (period & 0xFFu));
}
/// UPOS: upper position; reading it latches LPOS into LPOSH. RM §56.8, ENC_UPOS.
inline Reg16 upos(unsigned index) { return reg16(base(index) + 0x0Eu); }
/// LPOSH: lower position hold, latched by the UPOS read. RM §56.8, ENC_LPOSH.
inline Reg16 lposh(unsigned index) { return reg16(base(index) + 0x14u); }
/// UPOSH: upper position hold, latched with LPOSH by a UPOS read or (CTRL2 UPDHLD) a TRIGGER
/// edge. RM §56.8, ENC_UPOSH.
inline Reg16 uposh(unsigned index) { return reg16(base(index) + 0x12u); }
/// UINIT / LINIT: upper / lower initial position. RM §56.8, ENC_UINIT, ENC_LINIT.
inline Reg16 uinit(unsigned index) { return reg16(base(index) + 0x16u); }
inline Reg16 linit(unsigned index) { return reg16(base(index) + 0x18u); }
/// CTRL2: control 2; 0 = free 32-bit counting, no modulus, no interrupts; UPDHLD (bit 0): the
/// TRIGGER input's rising edge updates the hold registers. RM §56.8, ENC_CTRL2.
inline Reg16 ctrl2(unsigned index) { return reg16(base(index) + 0x1Eu); }
constexpr uint16_t kCtrl2UpdateHoldsOnTrigger = 1u << 0;
/// UMOD / LMOD: modulus (unused, kept 0). RM §56.8, ENC_UMOD, ENC_LMOD.
inline Reg16 umod(unsigned index) { return reg16(base(index) + 0x20u); }
inline Reg16 lmod(unsigned index) { return reg16(base(index) + 0x22u); }

}  // namespace stepdance::platform::teensy::regs::enc

#endif  // __IMXRT1062__
