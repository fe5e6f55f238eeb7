// A small non-volatile byte store (EEPROM emulation in flash on a Teensy 4.x, a file of the
// board's storage folder in the simulator) as the core sees it: settings that survive a reset.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "stepdance/core/status.hpp"

namespace stepdance {

/// Fixed-size byte array that keeps its contents across resets and power cycles. Bytes never
/// written read as 0xFF (erased flash). Context: loop only, and only while no motion runs: a
/// write may hold interrupts off while flash is programmed (milliseconds on a Teensy 4.x).
class NonvolatileStore {
 public:
  /// Capacity in bytes (1080 on a Teensy 4.0, 4284 on a 4.1; 0 where there is no store).
  virtual size_t size_bytes() = 0;
  /// Copies `length` bytes from `offset`. kBadArgument if the range exceeds size_bytes().
  virtual Status read(size_t offset, uint8_t* data, size_t length) = 0;
  /// Stores `length` bytes at `offset` (bytes that already hold the value are not rewritten).
  /// kBadArgument if the range exceeds size_bytes(), kIoError if the medium refused.
  virtual Status write(size_t offset, const uint8_t* data, size_t length) = 0;

 protected:
  // Never deleted through this base (see ByteStream).
  ~NonvolatileStore() = default;
};

}  // namespace stepdance
