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
/// A runaway sketch cannot fill the host's disk or use up the simulator's file descriptors: see
/// the two limits below.
class BoardStorage {
 public:
  /// At most this many files open at once: a further open() fails with kFull.
  static constexpr int kMaxOpenFiles = 16;
  /// The card takes at most this many bytes written in one run (the sketch server's file-size
  /// limit, docs/web.md): a write that would pass it fails with kFull and writes nothing, as on
  /// a full card.
  static constexpr uint64_t kWriteLimitBytes = uint64_t{64} << 20;

  explicit BoardStorage(std::string directory) : directory_(std::move(directory)) {}

  /// mode: 0 read, 1 write (truncate), 2 append — the values of stepdance::FileMode.
  Status open(const char* name, int mode, int& handle);
  Status read(int handle, uint8_t* data, size_t length, size_t& read);
  Status write(int handle, const uint8_t* data, size_t length);
  Status close(int handle);

  /// Bytes written so far (all files, this run).
  uint64_t written_bytes() const { return written_bytes_; }
  /// Writes refused by kWriteLimitBytes, and their bytes.
  uint64_t refused_writes() const { return refused_writes_; }
  uint64_t refused_write_bytes() const { return refused_write_bytes_; }
  /// Opens refused by kMaxOpenFiles.
  uint64_t refused_opens() const { return refused_opens_; }

 private:
  static bool valid_name(const char* name);

  std::string directory_;
  uint64_t written_bytes_ = 0;
  uint64_t refused_writes_ = 0;
  uint64_t refused_write_bytes_ = 0;
  uint64_t refused_opens_ = 0;
  std::map<int, std::unique_ptr<std::fstream>> open_files_;
  int next_handle_ = 0;
};

}  // namespace stepdance::sim
