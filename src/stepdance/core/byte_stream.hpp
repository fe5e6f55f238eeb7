// A byte stream (USB serial, UART, simulated pseudo-terminal) as the core's parsers see it.
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace stepdance {

/// Non-blocking byte I/O. Implemented by each backend's serial ports. Context: loop only.
class ByteStream {
 public:
  /// Bytes that read_byte() can return without waiting.
  virtual size_t bytes_available() = 0;
  /// Next byte, or -1 if none is waiting.
  virtual int read_byte() = 0;
  /// Queues up to length bytes for sending; returns how many were accepted (never blocks).
  virtual size_t write_bytes(const uint8_t* data, size_t length) = 0;
  /// Room for write_bytes() without refusing anything.
  virtual size_t write_space() = 0;

 protected:
  // Streams are never deleted through this base: no virtual destructor, so no operator delete
  // (and no free()) is linked into firmware images.
  ~ByteStream() = default;
};

}  // namespace stepdance
