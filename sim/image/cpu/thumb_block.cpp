// Thumb-2 instruction classes (ARMv7-M Architecture Reference Manual, DDI 0403E, A5.2 and A5.3).
#include "image/cpu/thumb_block.hpp"

namespace stepdance::sim::image {
namespace {

constexpr uint8_t kSp = 13;
constexpr uint8_t kPc = 15;
constexpr uint8_t kNone = 0xFF;

struct Class {
  uint8_t base = kNone;  ///< kNone: no memory access
  bool multiple = false;
};

// 16-bit encodings (A5.2): load/store single (0101, 011x, 1000), SP-relative (1001), literal
// (01001), PUSH/POP (1011 x10x), LDM/STM (1100).
Class classify16(uint16_t hw) {
  if ((hw >> 11) == 0x09) return {kPc, false};                      // LDR (literal)
  if ((hw >> 12) == 0x5 || (hw >> 13) == 0x3 || (hw >> 12) == 0x8) {  // register / immediate forms
    return {static_cast<uint8_t>((hw >> 3) & 7), false};
  }
  if ((hw >> 12) == 0x9) return {kSp, false};                        // STR/LDR SP-relative
  if ((hw & 0xF600) == 0xB400) return {kSp, true};                   // PUSH, POP
  if ((hw >> 12) == 0xC) return {static_cast<uint8_t>((hw >> 8) & 7), true};  // STM, LDM
  return {};
}

// 32-bit encodings (A5.3): load/store multiple (1110 100x x0), dual/exclusive/table branch
// (1110 100x x1), single data items (1111 100x), coprocessor/FP loads and stores (111x 110x).
Class classify32(uint16_t hw1) {
  const auto rn = static_cast<uint8_t>(hw1 & 0xF);
  if ((hw1 & 0xFE40) == 0xE800) return {rn, true};        // LDM/STM (PUSH.W/POP.W use SP)
  if ((hw1 & 0xFE40) == 0xE840) return {rn, (hw1 & 0x0120) != 0 || (hw1 & 0x0080) != 0};  // LDRD/STRD, LDREX, TBB
  if ((hw1 & 0xFE00) == 0xF800) return {rn, false};       // LDR/STR (byte, half, word)
  if ((hw1 & 0xEE00) == 0xEC00 && (hw1 & 0xFFE0) != 0xEC40) return {rn, true};  // VLDR/VSTR/VLDM/VSTM
  return {};
}

// `b .` (16-bit 0xE7FE) or `b.w .` (0xF7FF 0xBFFE).
bool branches_to_itself(const uint8_t* code, unsigned length) {
  const auto hw1 = static_cast<uint16_t>(code[0] | code[1] << 8);
  if (length == 2) return hw1 == 0xE7FE;
  const auto hw2 = static_cast<uint16_t>(code[2] | code[3] << 8);
  return hw1 == 0xF7FF && hw2 == 0xBFFE;
}

}  // namespace

ThumbBlock decode_thumb_block(uint32_t address, const uint8_t* code, size_t bytes) {
  ThumbBlock block;
  size_t offset = 0;
  while (offset + 2 <= bytes) {
    const auto hw = static_cast<uint16_t>(code[offset] | code[offset + 1] << 8);
    const unsigned length = thumb_instruction_bytes(hw);
    const Class kind = length == 2 ? classify16(hw) : classify32(hw);
    if (kind.base != kNone && kind.base != kSp && kind.base != kPc) {
      block.accesses.push_back(
          {static_cast<uint16_t>(block.instructions), static_cast<uint16_t>(offset), kind.base, kind.multiple});
    }
    if (block.instructions == 0 && offset + length == bytes) block.branches_to_itself = branches_to_itself(code, length);
    ++block.instructions;
    offset += length;
  }
  (void)address;
  return block;
}

}  // namespace stepdance::sim::image
