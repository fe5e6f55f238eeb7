// FlexIO3: shifters and timers that shift the output ports' STEP/DIR frames.
// RM chapter 50 (FlexIO), memory map §50.5.
#pragma once

#if defined(__IMXRT1062__)

#include <stdint.h>

#include "stepdance/platform/teensy/regs_common.hpp"

namespace stepdance::platform::teensy::regs::flexio3 {

constexpr uint32_t kBase = 0x42020000u;  // RM §50.5, FLEXIO3 base address

/// CTRL: module control. RM §50.5, FLEXIO_CTRL.
inline Reg32 ctrl() { return reg32(kBase + 0x008u); }
constexpr uint32_t kCtrlEnable = 1u << 0;     // FLEXEN
constexpr uint32_t kCtrlSoftReset = 1u << 1;  // SWRST

/// SHIFTSTAT: shifter status flags, one bit per shifter. RM §50.5, FLEXIO_SHIFTSTAT.
inline Reg32 shiftstat() { return reg32(kBase + 0x010u); }
/// SHIFTERR: shifter error flags (write 1 to clear). RM §50.5, FLEXIO_SHIFTERR.
inline Reg32 shifterr() { return reg32(kBase + 0x014u); }
/// TIMSTAT: timer status flags (write 1 to clear). RM §50.5, FLEXIO_TIMSTAT.
inline Reg32 timstat() { return reg32(kBase + 0x018u); }
/// TIMIEN: timer status interrupt enables. RM §50.5, FLEXIO_TIMIEN.
inline Reg32 timien() { return reg32(kBase + 0x028u); }

/// SHIFTCTLn: shifter control. RM §50.5, FLEXIO_SHIFTCTLn.
inline Reg32 shiftctl(unsigned n) { return reg32(kBase + 0x080u + 4u * n); }
constexpr uint32_t shiftctl_timer(uint32_t timer) { return (timer & 7u) << 24; }  // TIMSEL
constexpr uint32_t kShiftctlPinOutput = 3u << 16;                                 // PINCFG = output
constexpr uint32_t shiftctl_pin(uint32_t pin) { return (pin & 0x1Fu) << 8; }      // PINSEL
constexpr uint32_t kShiftctlTransmit = 2u;                                        // SMOD = transmit

/// SHIFTCFGn: shifter configuration (start/stop bits, width). RM §50.5, FLEXIO_SHIFTCFGn.
inline Reg32 shiftcfg(unsigned n) { return reg32(kBase + 0x100u + 4u * n); }

/// SHIFTBUFn: shifter buffer, shifted out LSB first. RM §50.5, FLEXIO_SHIFTBUFn.
inline Reg32 shiftbuf(unsigned n) { return reg32(kBase + 0x200u + 4u * n); }

/// TIMCTLn: timer control. RM §50.5, FLEXIO_TIMCTLn.
inline Reg32 timctl(unsigned n) { return reg32(kBase + 0x400u + 4u * n); }
constexpr uint32_t timctl_trigger_timer(uint32_t timer) { return ((4u * timer + 3u) & 0x3Fu) << 24; }  // TRGSEL
constexpr uint32_t kTimctlTriggerActiveLow = 1u << 23;  // TRGPOL: trigger inverted
constexpr uint32_t kTimctlTriggerInternal = 1u << 22;   // TRGSRC
constexpr uint32_t kTimodDisabled = 0u;                 // TIMOD
constexpr uint32_t kTimodDual8Baud = 1u;
constexpr uint32_t kTimod16Bit = 3u;
constexpr uint32_t kTimodMask = 3u;

/// TIMCFGn: timer configuration. RM §50.5, FLEXIO_TIMCFGn.
inline Reg32 timcfg(unsigned n) { return reg32(kBase + 0x480u + 4u * n); }
constexpr uint32_t timcfg_disable(uint32_t timdis) { return (timdis & 7u) << 12; }  // TIMDIS
constexpr uint32_t timcfg_enable(uint32_t timena) { return (timena & 7u) << 8; }    // TIMENA
constexpr uint32_t kTimdisNever = 0u;
constexpr uint32_t kTimdisOnCompare = 2u;
constexpr uint32_t kTimenaAlways = 0u;
constexpr uint32_t kTimenaTriggerRising = 6u;

/// TIMCMPn: timer compare value. RM §50.5, FLEXIO_TIMCMPn.
inline Reg32 timcmp(unsigned n) { return reg32(kBase + 0x500u + 4u * n); }

}  // namespace stepdance::platform::teensy::regs::flexio3

#endif  // __IMXRT1062__
