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

// Address forms of the 16-bit loads and stores (A6.2.4): register offset (0101), word/byte
// immediate (011B), halfword immediate (1000), LDM/STM (1100).
void address16(uint16_t hw, BlockAccess& access) {
  if ((hw >> 12) == 0x5) {
    access.mode = AddressMode::kRegister;
    access.rm = (hw >> 6) & 7;
  } else if ((hw >> 13) == 0x3) {
    access.mode = AddressMode::kOffset;
    access.displacement = static_cast<int32_t>((hw >> 6) & 0x1F) * ((hw & 0x1000) ? 1 : 4);
  } else if ((hw >> 12) == 0x8) {
    access.mode = AddressMode::kOffset;
    access.displacement = static_cast<int32_t>((hw >> 6) & 0x1F) * 2;
  } else if ((hw >> 12) == 0xC) {
    access.mode = AddressMode::kRange;
    access.span = 4u * static_cast<uint32_t>(__builtin_popcount(hw & 0xFF));
  }
}

// Address forms of the 32-bit single loads and stores (A6.3.7-10: imm12, imm8 with P/U/W,
// register), LDRD/STRD (A6.3.6) and LDM/STM (A6.3.5).
void address32(uint16_t hw1, uint16_t hw2, BlockAccess& access) {
  if ((hw1 & 0xFE00) == 0xF800) {
    if (hw1 & 0x0080) {
      access.mode = AddressMode::kOffset;
      access.displacement = hw2 & 0xFFF;
    } else if ((hw2 & 0x0FC0) == 0) {
      access.mode = AddressMode::kRegister;
      access.rm = hw2 & 0xF;
      access.shift = (hw2 >> 4) & 3;
    } else if (hw2 & 0x0800) {
      const bool pre = (hw2 & 0x0400) != 0, up = (hw2 & 0x0200) != 0;
      access.mode = pre ? AddressMode::kOffset : AddressMode::kBase;
      access.displacement = pre ? (up ? 1 : -1) * static_cast<int32_t>(hw2 & 0xFF) : 0;
    }
  } else if ((hw1 & 0xFE40) == 0xE840 && (hw1 & 0x0120) != 0) {  // LDRD/STRD
    const bool pre = (hw1 & 0x0100) != 0, up = (hw1 & 0x0080) != 0;
    access.mode = AddressMode::kRange;
    access.displacement = pre ? (up ? 4 : -4) * static_cast<int32_t>(hw2 & 0xFF) : 0;
    access.span = 8;
  } else if ((hw1 & 0xFE40) == 0xE800) {  // LDM/STM: IA (01) or DB (10)
    const uint32_t bytes = 4u * static_cast<uint32_t>(__builtin_popcount(hw2));
    access.mode = AddressMode::kRange;
    access.displacement = (hw1 & 0x0180) == 0x0100 ? -static_cast<int32_t>(bytes) : 0;
    access.span = bytes;
  }
}

// 16-bit encodings (A5.2): load/store single (0101, 011x, 1000), SP-relative (1001), literal
// (01001), PUSH/POP (1011 x10x), LDM/STM (1100).
Class classify16(uint16_t hw) {
  if ((hw >> 11) == 0x09) return {kPc, false};                        // LDR (literal)
  if ((hw >> 12) == 0x5 || (hw >> 13) == 0x3 || (hw >> 12) == 0x8) {  // register / immediate forms
    return {static_cast<uint8_t>((hw >> 3) & 7), false};
  }
  if ((hw >> 12) == 0x9) return {kSp, false};                                 // STR/LDR SP-relative
  if ((hw & 0xF600) == 0xB400) return {kSp, true};                            // PUSH, POP
  if ((hw >> 12) == 0xC) return {static_cast<uint8_t>((hw >> 8) & 7), true};  // STM, LDM
  return {};
}

// 32-bit encodings (A5.3): load/store multiple (1110 100x x0), dual/exclusive/table branch
// (1110 100x x1), single data items (1111 100x), coprocessor/FP loads and stores (111x 110x).
Class classify32(uint16_t hw1) {
  const auto rn = static_cast<uint8_t>(hw1 & 0xF);
  if ((hw1 & 0xFE40) == 0xE800) return {rn, true};  // LDM/STM (PUSH.W/POP.W use SP)
  if ((hw1 & 0xFE40) == 0xE840) return {rn, (hw1 & 0x0120) != 0 || (hw1 & 0x0080) != 0};  // LDRD/STRD, LDREX, TBB
  if ((hw1 & 0xFE00) == 0xF800) return {rn, false};                                       // LDR/STR (byte, half, word)
  if ((hw1 & 0xEE00) == 0xEC00 && (hw1 & 0xFFE0) != 0xEC40) return {rn, true};            // VLDR/VSTR/VLDM/VSTM
  return {};
}

// Instructions that lower SP (A6.7): PUSH, SUB SP,#imm, MOV SP,Rm; PUSH.W (STMDB SP!), STR
// Rt,[SP,#-imm]!, SUB.W/SUBW SP,SP,#imm, SUB SP,SP,Rm (32-bit), VPUSH.
bool lowers_sp(uint16_t hw1, uint16_t hw2, unsigned length) {
  if (length == 2) return (hw1 & 0xFE00) == 0xB400 || (hw1 & 0xFF80) == 0xB080 || (hw1 & 0xFF87) == 0x4685;
  const bool rd_sp = (hw2 & 0x0F00) == 0x0D00;
  return hw1 == 0xE92D || (hw1 == 0xF84D && rd_sp) || ((hw1 & 0xFBEF) == 0xF1AD && rd_sp) ||
         ((hw1 & 0xFBFF) == 0xF2AD && rd_sp) || ((hw1 & 0xFFEF) == 0xEBAD && rd_sp) || (hw1 & 0xFFBF) == 0xED2D;
}

// SDIV (0xFB9x) and UDIV (0xFBBx) with hw2 bits [7:4] = 1111 (A6.7.111, A6.7.145).
bool is_divide(uint16_t hw1, uint16_t hw2) {
  return ((hw1 & 0xFFF0) == 0xFB90 || (hw1 & 0xFFF0) == 0xFBB0) && (hw2 & 0x00F0) == 0x00F0;
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
  block.bytes = static_cast<uint32_t>(bytes);
  size_t offset = 0;
  while (offset + 2 <= bytes) {
    const auto hw = static_cast<uint16_t>(code[offset] | code[offset + 1] << 8);
    const unsigned length = thumb_instruction_bytes(hw);
    const auto hw2 =
        static_cast<uint16_t>(offset + 4 <= bytes && length == 4 ? code[offset + 2] | code[offset + 3] << 8 : 0);
    const Class kind = length == 2 ? classify16(hw) : classify32(hw);
    if (lowers_sp(hw, hw2, length)) block.lowers_sp = true;
    if (length == 4 && is_divide(hw, hw2))
      block.divides.push_back({static_cast<uint16_t>(offset), static_cast<uint8_t>(hw2 & 0xF)});
    if (kind.base != kNone && kind.base != kSp && kind.base != kPc) {
      BlockAccess access;
      access.index = static_cast<uint16_t>(block.instructions);
      access.offset = static_cast<uint16_t>(offset);
      access.base = kind.base;
      access.multiple = kind.multiple;
      if (length == 2)
        address16(hw, access);
      else
        address32(hw, hw2, access);
      block.accesses.push_back(access);
    }
    if (block.instructions == 0 && offset + length == bytes)
      block.branches_to_itself = branches_to_itself(code, length);
    ++block.instructions;
    offset += length;
  }
  (void)address;
  return block;
}

}  // namespace stepdance::sim::image
