// PIT: the periodic interrupt timer whose channel 3 is the input sample clock. RM chapter 53
// (PIT), memory map §53.4. Only the registers the sample clock programs.
#pragma once

#if defined(__IMXRT1062__)

#include <stdint.h>

#include "stepdance/platform/teensy/regs_common.hpp"

namespace stepdance::platform::teensy::regs::pit {

constexpr uint32_t kBase = 0x40084000u;  // RM §53.4, PIT base address

/// MCR: module control; MDIS (bit 1, set at reset) stops every channel. RM §53.4, PIT_MCR.
inline Reg32 mcr() { return reg32(kBase + 0x000u); }
constexpr uint32_t kMcrModuleDisable = 1u << 1;
/// LDVALn: the channel counts LDVAL..0 and reloads, so it expires every LDVAL + 1 ticks; a new
/// value takes effect at the next expiry. RM §53.4, PIT_LDVALn.
inline Reg32 ldval(unsigned channel) { return reg32(kBase + 0x100u + 0x10u * channel); }
/// TCTRLn: TEN (bit 0) starts the channel from LDVAL; TIE (bit 1) and CHN (bit 2) stay 0 here.
/// RM §53.4, PIT_TCTRLn.
inline Reg32 tctrl(unsigned channel) { return reg32(kBase + 0x108u + 0x10u * channel); }
constexpr uint32_t kTctrlEnable = 1u << 0;
/// TFLGn: TIF (bit 0) sets at every expiry, write 1 to clear. RM §53.4, PIT_TFLGn.
inline Reg32 tflg(unsigned channel) { return reg32(kBase + 0x10Cu + 0x10u * channel); }
constexpr uint32_t kTflgExpired = 1u << 0;

}  // namespace stepdance::platform::teensy::regs::pit

#endif  // __IMXRT1062__
