// Decoded translation blocks by (address, size): the block hook's per-block lookup.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <unordered_map>

#include "image/cpu/thumb_block.hpp"

namespace stepdance::sim::image {

/// Remembers each block the emulator has run. A direct-mapped front table answers repeats
/// without hashing. Blocks are keyed by address and size: code rewritten in place with the same
/// block boundaries keeps its old decoding (firmware writes code to ITCM once, before running it).
class BlockCache {
 public:
  /// Reads the block's bytes; returns false if they cannot be read.
  using CodeReader = bool (*)(void* context, uint32_t address, uint8_t* bytes, size_t size);

  BlockCache(CodeReader reader, void* context) : reader_(reader), context_(context) {}
  /// The decoded block at `address` of `size` bytes (decoded on first sight).
  const ThumbBlock& get(uint32_t address, uint32_t size) {
    const uint64_t key = uint64_t{address} << 32 | size;
    Slot& slot = front_[(address >> 1) & (kFrontSlots - 1)];
    if (slot.block != nullptr && slot.key == key) return *slot.block;
    return miss(key, slot);
  }
  size_t size() const { return blocks_.size(); }

 private:
  static constexpr size_t kFrontSlots = 8192;
  struct Slot {
    uint64_t key = 0;
    const ThumbBlock* block = nullptr;
  };
  const ThumbBlock& miss(uint64_t key, Slot& slot);

  CodeReader reader_;
  void* context_;
  std::array<Slot, kFrontSlots> front_{};
  std::unordered_map<uint64_t, std::unique_ptr<ThumbBlock>> blocks_;
};

}  // namespace stepdance::sim::image
