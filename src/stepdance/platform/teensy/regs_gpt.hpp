// GPT2: the 1 kHz tick. RM chapter 52 (GPT), memory map §52.7.
#pragma once

#if defined(__IMXRT1062__)

#include <stdint.h>

#include "stepdance/platform/teensy/regs_common.hpp"

namespace stepdance::platform::teensy::regs::gpt2 {

constexpr uint32_t kBase = 0x401F0000u;  // RM §52.7, GPT2 base address

/// CR: control. RM §52.7, GPT_CR.
inline Reg32 cr() { return reg32(kBase + 0x00u); }
constexpr uint32_t kCrEnable = 1u << 0;                                       // EN
constexpr uint32_t kCrEnableResets = 1u << 1;                                 // ENMOD
constexpr uint32_t cr_clock_source(uint32_t src) { return (src & 7u) << 6; }  // CLKSRC: 1 = PERCLK
constexpr uint32_t kCrSoftwareReset = 1u << 15;                               // SWR
/// PR: prescaler (PRESCALER bits 11:0, divide by n+1). RM §52.7, GPT_PR.
inline Reg32 pr() { return reg32(kBase + 0x04u); }
/// SR: status (OF1 bit 0, write 1 to clear). RM §52.7, GPT_SR.
inline Reg32 sr() { return reg32(kBase + 0x08u); }
constexpr uint32_t kSrCompare1 = 1u << 0;
constexpr uint32_t kSrAllFlags = 0x3Fu;
/// IR: interrupt enables (OF1IE bit 0). RM §52.7, GPT_IR.
inline Reg32 ir() { return reg32(kBase + 0x0Cu); }
/// OCR1: output compare 1; in restart mode (FRR = 0) the counter restarts after it. RM §52.7.
inline Reg32 ocr1() { return reg32(kBase + 0x10u); }

}  // namespace stepdance::platform::teensy::regs::gpt2

#endif  // __IMXRT1062__
