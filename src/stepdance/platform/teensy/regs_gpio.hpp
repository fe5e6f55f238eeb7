// Fast GPIO6..GPIO9 (the single-cycle aliases of GPIO1..GPIO4). RM chapter 12, memory map §12.5.
#pragma once

#if defined(__IMXRT1062__)

#include <stdint.h>

#include "stepdance/platform/teensy/regs_common.hpp"

namespace stepdance::platform::teensy::regs::gpio {

/// Base of fast GPIO port 6 + index (index 0..3 = GPIO6..GPIO9). RM §12.5.
constexpr uint32_t base(unsigned fast_index) { return 0x42000000u + 0x4000u * fast_index; }

/// DR: data register. RM §12.5, GPIO_DR.
inline Reg32 dr(unsigned fast_index) { return reg32(base(fast_index) + 0x00u); }
/// GDIR: direction, 1 = output. RM §12.5, GPIO_GDIR.
inline Reg32 gdir(unsigned fast_index) { return reg32(base(fast_index) + 0x04u); }
/// PSR: pad status (the level on the pin). RM §12.5, GPIO_PSR.
inline Reg32 psr(unsigned fast_index) { return reg32(base(fast_index) + 0x08u); }
/// DR_SET: write 1 to set DR bits. RM §12.5, GPIO_DR_SET.
inline Reg32 dr_set(unsigned fast_index) { return reg32(base(fast_index) + 0x84u); }
/// DR_CLEAR: write 1 to clear DR bits. RM §12.5, GPIO_DR_CLEAR.
inline Reg32 dr_clear(unsigned fast_index) { return reg32(base(fast_index) + 0x88u); }

}  // namespace stepdance::platform::teensy::regs::gpio

#endif  // __IMXRT1062__
