// What the CPU needs to know about one translation block of Thumb-2 code: how many instructions
// it holds and which of them may reach memory through a general register.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace stepdance::sim::image {

/// Bytes (2 or 4) of the Thumb instruction whose first halfword is `first` (ARMv7-M ARM A5.1:
/// bits [15:11] 0b11101, 0b11110 or 0b11111 start a 32-bit instruction).
constexpr unsigned thumb_instruction_bytes(uint16_t first) { return (first >> 11) >= 0x1D ? 4 : 2; }

/// How a load or store forms its address from its base register Rn (ARMv7-M A7.7).
enum class AddressMode : uint8_t {
  kOffset,    ///< Rn + offset (offset and pre-indexed forms)
  kBase,      ///< Rn (post-indexed forms)
  kRegister,  ///< Rn + (Rm << shift)
  kRange,     ///< somewhere in [Rn + offset, Rn + offset + span) (LDM/STM, LDRD/STRD)
  kAny,       ///< not decoded (exclusive, table branch, FP loads and stores)
};

/// A load or store in a block whose address comes from a general register (not SP, not PC):
/// the only kind that can reach a peripheral.
struct BlockAccess {
  uint16_t index = 0;     ///< instructions before it in the block
  uint16_t offset = 0;    ///< its byte offset in the block
  uint8_t base = 0;       ///< its base register Rn
  bool multiple = false;  ///< LDM/STM/LDRD/STRD/VLDM/VSTM: more than one access
  AddressMode mode = AddressMode::kAny;
  uint8_t rm = 0;            ///< kRegister: the index register
  uint8_t shift = 0;         ///< kRegister: its left shift
  int32_t displacement = 0;  ///< kOffset, kRange: added to Rn
  uint32_t span = 0;         ///< kRange: bytes
};

/// An SDIV or UDIV in a block (its divisor register Rm), for CCR.DIV_0_TRP.
struct BlockDivide {
  uint16_t offset = 0;  ///< byte offset in the block
  uint8_t rm = 0;
};

/// One decoded block: the instruction count and the peripheral-capable accesses, in order.
struct ThumbBlock {
  uint32_t bytes = 0;
  uint32_t instructions = 0;
  std::vector<BlockAccess> accesses;
  std::vector<BlockDivide> divides;
  /// True if an instruction lowers SP (PUSH, SUB SP, STR/STMDB/VPUSH with SP writeback, MOV SP).
  bool lowers_sp = false;
  /// True if the block is one instruction that branches to itself (`b .`).
  bool branches_to_itself = false;
};

/// Decodes `bytes` of Thumb code starting at `address` (the block as the emulator translated it).
ThumbBlock decode_thumb_block(uint32_t address, const uint8_t* code, size_t bytes);

}  // namespace stepdance::sim::image
