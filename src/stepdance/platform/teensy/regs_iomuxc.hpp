// IOMUXC: pad multiplexing, pad electrical settings, input (daisy) selects and the GPRs we use.
// RM chapter 11: IOMUXC_GPR §11.4, IOMUXC §11.7.
#pragma once

#if defined(__IMXRT1062__)

#include <stdint.h>

#include "stepdance/platform/teensy/regs_common.hpp"

namespace stepdance::platform::teensy::regs::iomuxc {

constexpr uint32_t kBase = 0x401F8000u;     // RM §11.7, IOMUXC memory map
constexpr uint32_t kGprBase = 0x400AC000u;  // RM §11.4, IOMUXC_GPR memory map

// ---- Pads: SW_MUX_CTL_PAD_GPIO_<pad> at kBase + mux offset, SW_PAD_CTL_PAD_GPIO_<pad> 0x1F0 later.
// Mux offsets of the first pad of each bank (RM §11.7); pads within a bank are 4 bytes apart.
constexpr uint16_t kMuxEmc00 = 0x014;
constexpr uint16_t kMuxAdB000 = 0x0BC;
constexpr uint16_t kMuxAdB100 = 0x0FC;
constexpr uint16_t kMuxB000 = 0x13C;
constexpr uint16_t kMuxB100 = 0x17C;
constexpr uint16_t kMuxSdB000 = 0x1BC;
constexpr uint16_t kPadCtlFromMux = 0x1F0;

/// SW_MUX_CTL_PAD register of a pad. RM §11.7.
inline Reg32 pad_mux(uint16_t mux_offset) { return reg32(kBase + mux_offset); }
/// SW_PAD_CTL_PAD register of the same pad. RM §11.7.
inline Reg32 pad_ctl(uint16_t mux_offset) { return reg32(kBase + mux_offset + kPadCtlFromMux); }

// SW_MUX_CTL_PAD fields (RM §11.7): MUX_MODE bits 3:0, SION bit 4.
constexpr uint32_t kMuxSion = 1u << 4;
constexpr uint32_t kMuxModeMask = 0xFu;
constexpr uint32_t kAltGpio = 5;     // ALT5 is GPIO on every pad we use
constexpr uint32_t kAltFlexio3 = 9;  // ALT9 is FlexIO3 on the AD_B1 and B1 pads we use

// SW_PAD_CTL_PAD fields (RM §11.7).
constexpr uint32_t kPadSlewFast = 1u << 0;                                  // SRE
constexpr uint32_t pad_drive(uint32_t dse) { return (dse & 7u) << 3; }      // DSE: R0/dse, 0 = output off
constexpr uint32_t pad_speed(uint32_t speed) { return (speed & 3u) << 6; }  // SPEED
constexpr uint32_t kPadOpenDrain = 1u << 11;                                // ODE
constexpr uint32_t kPadKeeperEnable = 1u << 12;                             // PKE
constexpr uint32_t kPadPullSelect = 1u << 13;                               // PUE: 1 = pull, 0 = keeper
constexpr uint32_t pad_pull(uint32_t pus) { return (pus & 3u) << 14; }      // PUS
constexpr uint32_t kPull100kDown = 0;
constexpr uint32_t kPull22kUp = 3;
constexpr uint32_t kPadHysteresis = 1u << 16;  // HYS

// ---- Input (daisy) selects, at kBase + offset. RM §11.7, IOMUXC_*_SELECT_INPUT.
constexpr uint16_t kSelectFlexpwm1PwmA3 = 0x454;
constexpr uint16_t kSelectFlexpwm2PwmA0 = 0x478;
constexpr uint16_t kSelectFlexpwm2PwmA1 = 0x47C;
constexpr uint16_t kSelectFlexpwm2PwmB2 = 0x490;
constexpr uint16_t kSelectXbar1In06 = 0x61C;
constexpr uint16_t kSelectXbar1In07 = 0x620;
constexpr uint16_t kSelectXbar1In16 = 0x64C;
constexpr uint16_t kSelectXbar1In17 = 0x62C;

/// An IOMUXC_*_SELECT_INPUT register. RM §11.7.
inline Reg32 select_input(uint16_t offset) { return reg32(kBase + offset); }

// ---- General-purpose registers (RM §11.4).
/// GPR6: XBAR_INOUTn direction select, bit (n + 12) for n = 4..19; 0 = input.
inline Reg32 gpr6() { return reg32(kGprBase + 0x18u); }
constexpr uint32_t gpr6_xbar_output(unsigned inout) { return 1u << (inout + 12u); }

/// GPR26..GPR29: per-bit choice between GPIO1..4 (0) and the fast GPIO6..9 (1).
inline Reg32 gpr_fast_gpio_select(unsigned fast_gpio_index) { return reg32(kGprBase + 0x68u + 4u * fast_gpio_index); }

}  // namespace stepdance::platform::teensy::regs::iomuxc

#endif  // __IMXRT1062__
