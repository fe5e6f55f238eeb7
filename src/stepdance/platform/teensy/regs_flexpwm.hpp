// eFlexPWM1/2 submodules used as free-running input-capture timers for the input ports.
// RM chapter 55 (eFlexPWM), memory map §55.8. All registers are 16 bits wide.
#pragma once

#if defined(__IMXRT1062__)

#include <stdint.h>

#include "stepdance/platform/teensy/regs_common.hpp"

namespace stepdance::platform::teensy::regs::flexpwm {

constexpr uint32_t kPwm1Base = 0x403DC000u;  // RM §55.8, PWM1 base address
constexpr uint32_t kPwm2Base = 0x403E0000u;  // RM §55.8, PWM2 base address
constexpr uint32_t kSubmoduleStride = 0x60u;

/// A register of submodule `sm` at `offset` (RM §55.8, SMn* registers).
inline Reg16 sm_reg(uint32_t base, unsigned sm, uint32_t offset) {
  return reg16(base + kSubmoduleStride * sm + offset);
}
constexpr uint32_t kSmCnt = 0x00;        // SMnCNT: the counter (read only)
constexpr uint32_t kSmInit = 0x02;       // SMnINIT: counter start value
constexpr uint32_t kSmCtrl2 = 0x04;      // SMnCTRL2
constexpr uint32_t kSmCtrl = 0x06;       // SMnCTRL
constexpr uint32_t kSmVal0 = 0x0A;       // SMnVAL0
constexpr uint32_t kSmVal1 = 0x0E;       // SMnVAL1: counter modulo (end value)
constexpr uint32_t kSmVal2 = 0x12;       // SMnVAL2..VAL5 every 4 bytes
constexpr uint32_t kSmOctrl = 0x22;      // SMnOCTRL
constexpr uint32_t kSmSts = 0x24;        // SMnSTS: flags, write 1 to clear
constexpr uint32_t kSmInten = 0x26;      // SMnINTEN
constexpr uint32_t kSmCaptctrlA = 0x34;  // SMnCAPTCTRLA
constexpr uint32_t kSmCaptctrlB = 0x38;  // SMnCAPTCTRLB
constexpr uint32_t kSmCval2 = 0x48;      // SMnCVAL2: capture A0 (reading pops its FIFO)
constexpr uint32_t kSmCval3 = 0x4C;      // SMnCVAL3: capture A1
constexpr uint32_t kSmCval4 = 0x50;      // SMnCVAL4: capture B0
constexpr uint32_t kSmCval5 = 0x54;      // SMnCVAL5: capture B1

// SMnCTRL2 fields (RM §55.8): INDEP bit 13, CLK_SEL bits 1:0 (0 = IPG clock).
constexpr uint16_t kCtrl2Independent = 1u << 13;
// SMnCTRL fields: FULL bit 10 (reload every full cycle), PRSC bits 6:4 (0 = no prescaler).
constexpr uint16_t kCtrlFullReload = 1u << 10;

// SMnSTS / SMnINTEN capture bits (RM §55.8): CFB0 8, CFB1 9, CFA0 10, CFA1 11 (and CxxIE alike).
constexpr uint16_t kCaptureB0 = 1u << 8;
constexpr uint16_t kCaptureB1 = 1u << 9;
constexpr uint16_t kCaptureA0 = 1u << 10;
constexpr uint16_t kCaptureA1 = 1u << 11;
// SMnSTS RF / SMnINTEN RIE, bit 12 (RM §55.8): set at every reload, i.e. every counter wrap here.
constexpr uint16_t kReload = 1u << 12;

// SMnCAPTCTRLA/B fields (RM §55.8): ARM bit 0, ONESHOT bit 1 (0 = free running, circuits 0 and 1
// alternate), EDGx0 bits 3:2, EDGx1 bits 5:4 (1 = falling, 2 = rising).
constexpr uint16_t kCaptArm = 1u << 0;
constexpr uint16_t kCaptEdge0Rising = 2u << 2;
constexpr uint16_t kCaptEdge1Falling = 1u << 4;

/// OUTEN: output enables (PWMA_EN bits 11:8, PWMB_EN bits 7:4, one bit per submodule). RM §55.8.
inline Reg16 outen(uint32_t base) { return reg16(base + 0x180u); }
constexpr uint16_t outen_a(unsigned sm) { return static_cast<uint16_t>(1u << (8u + sm)); }
constexpr uint16_t outen_b(unsigned sm) { return static_cast<uint16_t>(1u << (4u + sm)); }

/// MCTRL: master control (RUN bits 11:8, CLDOK bits 7:4, LDOK bits 3:0). RM §55.8.
inline Reg16 mctrl(uint32_t base) { return reg16(base + 0x188u); }
constexpr uint16_t mctrl_run(unsigned sm) { return static_cast<uint16_t>(1u << (8u + sm)); }
constexpr uint16_t mctrl_clear_load_ok(unsigned sm) { return static_cast<uint16_t>(1u << (4u + sm)); }
constexpr uint16_t mctrl_load_ok(unsigned sm) { return static_cast<uint16_t>(1u << sm); }

}  // namespace stepdance::platform::teensy::regs::flexpwm

#endif  // __IMXRT1062__
