// DWT cycle counter and the debug control bit that powers it (ARMv7-M ARM §C1.8 and §C1.6.5).
#pragma once

#if defined(__IMXRT1062__)

#include <stdint.h>

#include "stepdance/platform/teensy/regs_common.hpp"

namespace stepdance::platform::teensy::regs::dwt {

/// DEMCR: debug exception and monitor control; TRCENA (bit 24) powers the DWT.
/// ARMv7-M ARM §C1.6.5.
inline Reg32 demcr() { return reg32(0xE000EDFCu); }
constexpr uint32_t kDemcrTraceEnable = 1u << 24;
/// DWT_CTRL: CYCCNTENA (bit 0) starts the cycle counter. ARMv7-M ARM §C1.8.7.
inline Reg32 ctrl() { return reg32(0xE0001000u); }
constexpr uint32_t kCtrlCycleCounterEnable = 1u << 0;
/// DWT_CYCCNT: core clock cycles, wrapping at 2^32. ARMv7-M ARM §C1.8.8.
inline Reg32 cyccnt() { return reg32(0xE0001004u); }
/// DWT_LAR: the Cortex-M7 lock access register; this key unlocks writes. ARMv7-M ARM §D1.2 /
/// Cortex-M7 TRM (CoreSight lock).
inline Reg32 lar() { return reg32(0xE0001FB0u); }
constexpr uint32_t kLarUnlockKey = 0xC5ACCE55u;

}  // namespace stepdance::platform::teensy::regs::dwt

#endif  // __IMXRT1062__
