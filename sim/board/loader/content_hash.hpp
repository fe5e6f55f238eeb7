// A 64-bit FNV-1a hash for cache keys (sketch text, flags, runtime library contents).
#pragma once

#include <cstdint>
#include <string>

namespace stepdance::sim {

/// Accumulates bytes into a 64-bit FNV-1a hash. Not cryptographic: it only has to tell
/// different sketch builds apart.
class ContentHash {
 public:
  /// Adds bytes, then a separator, so ("ab","c") and ("a","bc") differ.
  void add(const std::string& bytes);
  /// Adds a file's contents (or a marker if it cannot be read). Returns false if unreadable.
  bool add_file(const std::string& path);
  /// The hash as 16 lowercase hex digits.
  std::string hex() const;

 private:
  void add_byte(uint8_t byte) { value_ = (value_ ^ byte) * 0x100000001b3ull; }
  uint64_t value_ = 0xcbf29ce484222325ull;
};

}  // namespace stepdance::sim
