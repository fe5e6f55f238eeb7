// XBARA1: routes the encoder pads to the ENC phase inputs, and the sample clock to their TRIGGER. RM chapter 61 (XBAR),
// memory map §61.4; input and output numbers from RM chapter 4 (XBAR1 input/output assignments).
#pragma once

#if defined(__IMXRT1062__)

#include <stdint.h>

#include "stepdance/platform/teensy/regs_common.hpp"

namespace stepdance::platform::teensy::regs::xbar1 {

constexpr uint32_t kBase = 0x403BC000u;  // RM §61.4, XBARA1 base address

/// Connects XBAR1 input `input` to output `output`: SELn (16 bits at 2n) holds output 2n in
/// bits 6:0 and output 2n+1 in bits 14:8. RM §61.4, XBARA_SELn.
inline void connect(uint8_t input, uint8_t output) {
  Reg16 sel = reg16(kBase + 2u * (output / 2u));
  const unsigned shift = (output & 1u) ? 8u : 0u;
  sel = static_cast<uint16_t>((sel & ~(0x7Fu << shift)) | ((input & 0x7Fu) << shift));
}

// Outputs (RM chapter 4, XBAR1 output assignments).
constexpr uint8_t kOutEnc1PhaseA = 66;
constexpr uint8_t kOutEnc1PhaseB = 67;
constexpr uint8_t kOutEnc2PhaseA = 71;
constexpr uint8_t kOutEnc2PhaseB = 72;
/// ENCn TRIGGER: with CTRL2 UPDHLD its rising edge copies the position into the hold registers.
constexpr uint8_t kOutEnc1Trigger = 70;
constexpr uint8_t kOutEnc2Trigger = 75;
/// PIT_TRIGGERn, a pulse at every expiry of PIT channel n (RM chapter 4, XBAR1 input assignments).
constexpr uint8_t in_pit_trigger(unsigned channel) { return static_cast<uint8_t>(56u + channel); }
// Inputs IOMUX_XBAR_INOUTnn are XBAR1 input number nn (RM chapter 4, XBAR1 input assignments).

}  // namespace stepdance::platform::teensy::regs::xbar1

#endif  // __IMXRT1062__
