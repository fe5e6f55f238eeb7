// File storage (SD card on a Teensy 4.1, a folder in the simulator) as the core sees it.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "stepdance/core/byte_stream.hpp"
#include "stepdance/core/status.hpp"

namespace stepdance {

/// How a file is opened.
enum class FileMode : uint8_t { kRead, kWriteTruncate, kAppend };

/// Minimal file access for recordings and programs. Context: loop only (it may block on I/O).
class FileStorage {
 public:
  /// Opens `name` (at most kMaxNameLength characters) and returns a handle ≥ 0, or a status.
  virtual Status open(const char* name, FileMode mode, int& handle) = 0;
  /// Reads up to length bytes; `read` receives the count (0 at end of file).
  virtual Status read(int handle, uint8_t* data, size_t length, size_t& read) = 0;
  /// Writes all length bytes or fails with kIoError.
  virtual Status write(int handle, const uint8_t* data, size_t length) = 0;
  /// Flushes and releases the handle.
  virtual Status close(int handle) = 0;
  /// Longest file name accepted by open().
  static constexpr size_t kMaxNameLength = 63;

 protected:
  // Never deleted through this base (see ByteStream).
  ~FileStorage() = default;
};

}  // namespace stepdance
