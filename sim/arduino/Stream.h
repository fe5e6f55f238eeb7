// Arduino's Stream on the host: a Print that can also be read, with timed parsing helpers.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "Print.h"
#include "WString.h"

/// A readable and writable byte stream. Subclasses implement available(), read(), peek() and
/// Print's write().
///
/// The helpers below wait for bytes up to the timeout (default 1000 ms) of board time. Waiting
/// lets board time pass through arduino_backend::delay_us in 1 ms steps, so frames keep running
/// and the simulator can deliver the awaited bytes. Context: loop.
class Stream : public Print {
 public:
  /// The timeout a Stream starts with, in milliseconds.
  static constexpr unsigned long kDefaultTimeoutMs = 1000;

  /// Bytes that read() can return without waiting.
  virtual int available() = 0;
  /// The next byte (0..255), or −1 if none is waiting.
  virtual int read() = 0;
  /// The next byte without consuming it, or −1 if none is waiting.
  virtual int peek() = 0;

  /// How long the helpers below wait for a byte, in ms of board time.
  void setTimeout(unsigned long timeout_ms) { timeout_ms_ = timeout_ms; }
  unsigned long getTimeout() const { return timeout_ms_; }

  /// Reads until `target` has been read (true) or the timeout passes (false).
  bool find(const char* target);
  bool find(char target);
  /// Skips anything that is not a digit or '-', then reads an optional '-' and digits.
  /// Returns 0 if no digit arrives in time.
  long parseInt();
  /// As parseInt(), with an optional fraction after a '.' (a number may also start with '.').
  float parseFloat();
  /// Reads up to length bytes, stopping at the timeout; returns how many were read.
  size_t readBytes(char* buffer, size_t length);
  size_t readBytes(uint8_t* buffer, size_t length) { return readBytes(reinterpret_cast<char*>(buffer), length); }
  /// As readBytes(), also stopping at (and consuming, not storing) `terminator`.
  size_t readBytesUntil(char terminator, char* buffer, size_t length);
  size_t readBytesUntil(char terminator, uint8_t* buffer, size_t length) {
    return readBytesUntil(terminator, reinterpret_cast<char*>(buffer), length);
  }
  /// Everything that arrives until the timeout passes with no byte.
  String readString();
  /// Everything up to `terminator` (consumed, not included) or the timeout.
  String readStringUntil(char terminator);

 protected:
  /// read() / peek(), waiting up to the timeout for a byte; −1 on timeout.
  int timedRead();
  int timedPeek();
  /// Puts a Stream back to its power-on settings (the timeout).
  void reset_stream_settings() { timeout_ms_ = kDefaultTimeoutMs; }

 private:
  // Waits for a byte to become available; false when the timeout passed first.
  bool wait_for_byte();
  // Skips what cannot start a number ('.' can when allow_point), then reads an optional '-'
  // and a run of digits into value. False if the timeout passed before a number started.
  bool parse_integer_part(bool allow_point, bool& negative, long& value);

  unsigned long timeout_ms_ = kDefaultTimeoutMs;
};
