// A simulated board's SD card: files in one host folder, opened by handle.
#pragma once

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <map>
#include <memory>
#include <string>

#include "stepdance/core/status.hpp"

namespace stepdance::sim {

/// The storage behind hal::storage() of one board. Names are plain file names (no folders, no
/// "..", at most 63 characters) inside `directory`, which is created on the first write.
/// With an empty directory every open() fails with kUnsupported, like a board without a card.
class BoardStorage {
 public:
  explicit BoardStorage(std::string directory) : directory_(std::move(directory)) {}

  /// mode: 0 read, 1 write (truncate), 2 append — the values of stepdance::FileMode.
  Status open(const char* name, int mode, int& handle);
  Status read(int handle, uint8_t* data, size_t length, size_t& read);
  Status write(int handle, const uint8_t* data, size_t length);
  Status close(int handle);

 private:
  static bool valid_name(const char* name);

  std::string directory_;
  std::map<int, std::unique_ptr<std::fstream>> open_files_;
  int next_handle_ = 0;
};

}  // namespace stepdance::sim
