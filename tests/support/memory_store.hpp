// A NonvolatileStore in memory for tests: erased (0xFF) at construction, every byte inspectable.
#pragma once

#include <string.h>

#include <vector>

#include "stepdance/core/nonvolatile_store.hpp"

namespace stepdance::test_support {

class MemoryStore final : public NonvolatileStore {
 public:
  explicit MemoryStore(size_t bytes = 1080) : bytes_(bytes, 0xFF) {}
  size_t size_bytes() override { return bytes_.size(); }
  Status read(size_t offset, uint8_t* data, size_t length) override {
    if (offset > bytes_.size() || length > bytes_.size() - offset) return Status::kBadArgument;
    if (length > 0) memcpy(data, bytes_.data() + offset, length);
    return Status::kOk;
  }
  Status write(size_t offset, const uint8_t* data, size_t length) override {
    if (offset > bytes_.size() || length > bytes_.size() - offset) return Status::kBadArgument;
    if (refuse_writes) return Status::kIoError;
    if (length > 0) memcpy(bytes_.data() + offset, data, length);
    ++writes;
    return Status::kOk;
  }
  std::vector<uint8_t>& bytes() { return bytes_; }
  bool refuse_writes = false;
  int writes = 0;

 private:
  std::vector<uint8_t> bytes_;
};

}  // namespace stepdance::test_support
