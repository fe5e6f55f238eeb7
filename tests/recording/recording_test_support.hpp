// Shared pieces of the recording tests: a scripted source block and file helpers.
#pragma once

#include <stdint.h>

#include <string>
#include <vector>

#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/hal/storage.hpp"

namespace stepdance::test_support {

/// A pre-channel block whose output moves by script[i] world units in its i-th active frame.
class ScriptedSource : public Block {
 public:
  void begin() {
    output.begin(&position_, BLOCKPORT_OUTPUT, this);
    register_in(Stage::kPreChannel);
  }
  void play(std::vector<double> script) {
    script_ = std::move(script);
    next_ = 0;
  }
  void run() override {
    if (next_ < script_.size()) output.set(position_ + script_[next_++]);
    output.push();
  }
  BlockPort output;

 private:
  DecimalPosition position_ = 0;
  std::vector<double> script_;
  size_t next_ = 0;
};

/// A whole file from the board's storage (empty if it cannot be opened).
inline std::vector<uint8_t> read_file(const char* name) {
  std::vector<uint8_t> bytes;
  int handle = -1;
  if (hal::storage().open(name, FileMode::kRead, handle) != Status::kOk) return bytes;
  uint8_t chunk[256];
  size_t read = 0;
  do {
    hal::storage().read(handle, chunk, sizeof(chunk), read);
    bytes.insert(bytes.end(), chunk, chunk + read);
  } while (read > 0);
  hal::storage().close(handle);
  return bytes;
}

/// Writes a whole file to the board's storage.
inline void write_file(const char* name, const std::vector<uint8_t>& bytes) {
  int handle = -1;
  hal::storage().open(name, FileMode::kWriteTruncate, handle);
  hal::storage().write(handle, bytes.data(), bytes.size());
  hal::storage().close(handle);
}

inline void write_file(const char* name, const std::string& text) {
  write_file(name, std::vector<uint8_t>(text.begin(), text.end()));
}

}  // namespace stepdance::test_support
