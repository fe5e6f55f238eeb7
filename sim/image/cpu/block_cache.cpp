// Decoded translation blocks.
#include "image/cpu/block_cache.hpp"

#include <vector>

namespace stepdance::sim::image {

const ThumbBlock& BlockCache::miss(uint64_t key, Slot& slot) {
  auto found = blocks_.find(key);
  if (found == blocks_.end()) {
    const auto address = static_cast<uint32_t>(key >> 32);
    const auto size = static_cast<uint32_t>(key);
    std::vector<uint8_t> code(size);
    auto block = std::make_unique<ThumbBlock>();
    if (size > 0 && reader_(context_, address, code.data(), size)) {
      *block = decode_thumb_block(address, code.data(), size);
    }
    found = blocks_.emplace(key, std::move(block)).first;
  }
  slot.key = key;
  slot.block = found->second.get();
  return *slot.block;
}

}  // namespace stepdance::sim::image
