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

/// A load or store in a block whose address comes from a general register (not SP, not PC):
/// the only kind that can reach a peripheral.
struct BlockAccess {
  uint16_t index = 0;     ///< instructions before it in the block
  uint16_t offset = 0;    ///< its byte offset in the block
  uint8_t base = 0;       ///< its base register Rn
  bool multiple = false;  ///< LDM/STM/LDRD/STRD/VLDM/VSTM: more than one access
};

/// One decoded block: the instruction count and the peripheral-capable accesses, in order.
struct ThumbBlock {
  uint32_t instructions = 0;
  std::vector<BlockAccess> accesses;
  /// True if the block is one instruction that branches to itself (`b .`).
  bool branches_to_itself = false;
};

/// Decodes `bytes` of Thumb code starting at `address` (the block as the emulator translated it).
ThumbBlock decode_thumb_block(uint32_t address, const uint8_t* code, size_t bytes);

}  // namespace stepdance::sim::image
