// CCM (Clock Controller Module): the clock gates and clock roots this backend touches.
// RM chapter 14, register map §14.7.
#pragma once

#if defined(__IMXRT1062__)

#include <stdint.h>

#include "stepdance/platform/teensy/regs_common.hpp"

namespace stepdance::platform::teensy::regs::ccm {

constexpr uint32_t kBase = 0x400FC000u;  // RM §14.7, CCM memory map

/// CSCMR1: serial clock multiplexer 1. RM §14.7, CCM_CSCMR1.
inline Reg32 cscmr1() { return reg32(kBase + 0x1Cu); }
constexpr uint32_t kCscmr1PerclkSelOsc = 1u << 6;  // PERCLK_CLK_SEL: 1 = 24 MHz oscillator, 0 = IPG
constexpr uint32_t kCscmr1PerclkPodfMask = 0x3Fu;  // PERCLK_PODF, bits 5:0, divide by (n+1)

/// CSCMR2: serial clock multiplexer 2. RM §14.7, CCM_CSCMR2.
inline Reg32 cscmr2() { return reg32(kBase + 0x20u); }
constexpr unsigned kCscmr2Flexio2SelShift = 19;  // FLEXIO2_CLK_SEL, bits 20:19
constexpr uint32_t kCscmr2Flexio2SelMask = 3u << 19;
constexpr uint32_t kFlexio2SelPll3 = 3;  // 3 = PLL3 (480 MHz, USB1 PLL)

/// CS1CDR: clock divider for FlexIO2 (which also clocks FlexIO3). RM §14.7, CCM_CS1CDR.
inline Reg32 cs1cdr() { return reg32(kBase + 0x28u); }
constexpr unsigned kCs1cdrFlexio2PodfShift = 25;  // FLEXIO2_CLK_PODF, bits 27:25, divide by (n+1)
constexpr uint32_t kCs1cdrFlexio2PodfMask = 7u << 25;
constexpr unsigned kCs1cdrFlexio2PredShift = 9;  // FLEXIO2_CLK_PRED, bits 11:9, divide by (n+1)
constexpr uint32_t kCs1cdrFlexio2PredMask = 7u << 9;

/// CCGRn: clock gating registers, two bits per gate (CGx at bits 2x+1:2x). RM §14.7, CCM_CCGR0..7.
inline Reg32 ccgr(unsigned n) { return reg32(kBase + 0x68u + 4u * n); }

/// One clock gate: register index and CG slot.
struct ClockGate {
  uint8_t ccgr;
  uint8_t slot;
};

// The gates we switch, as listed in RM §14.7 (CCGRn field descriptions).
constexpr ClockGate kGateGpt2Bus = {0, 12};
constexpr ClockGate kGateGpt2Serial = {0, 13};
constexpr ClockGate kGateAdc2 = {1, 4};
constexpr ClockGate kGatePit = {1, 6};
constexpr ClockGate kGateAdc1 = {1, 8};
constexpr ClockGate kGateXbar1 = {2, 11};
constexpr ClockGate kGateFlexio2 = {3, 0};
constexpr ClockGate kGatePwm1 = {4, 8};
constexpr ClockGate kGatePwm2 = {4, 9};
constexpr ClockGate kGateEnc1 = {4, 12};
constexpr ClockGate kGateEnc2 = {4, 13};
constexpr ClockGate kGateFlexio3 = {7, 6};

/// Turns a gate fully on (0b11: on in run and wait modes).
inline void gate_on(ClockGate gate) { ccgr(gate.ccgr) |= 3u << (2u * gate.slot); }
/// Turns a gate off (0b00).
inline void gate_off(ClockGate gate) { ccgr(gate.ccgr) &= ~(3u << (2u * gate.slot)); }
/// True if the gate is on in run mode.
inline bool gate_is_on(ClockGate gate) { return ((ccgr(gate.ccgr) >> (2u * gate.slot)) & 3u) != 0; }

/// Frequency of PLL3 (USB1 PLL), fixed at 20 × the 24 MHz crystal whenever USB runs.
constexpr uint32_t kPll3Hz = 480000000u;
/// The crystal oscillator that can feed PERCLK.
constexpr uint32_t kOscillatorHz = 24000000u;

}  // namespace stepdance::platform::teensy::regs::ccm

#endif  // __IMXRT1062__
