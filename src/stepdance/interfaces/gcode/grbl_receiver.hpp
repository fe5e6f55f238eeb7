// Grbl's serial receive path: a 128-byte buffer, realtime bytes picked out, lines assembled.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "stepdance/core/byte_stream.hpp"

namespace stepdance::gcode {

/// True for the bytes Grbl acts on the moment they arrive and never stores: `?`, `!`, `~`,
/// Ctrl-X (0x18) and the extended set 0x80–0xFF (overrides, jog cancel, safety door).
/// Context: any.
inline bool is_realtime_byte(uint8_t byte) {
  return byte == '?' || byte == '!' || byte == '~' || byte == 0x18 || byte >= 0x80;
}

/// True for the control characters Grbl throws away while it assembles a line: every byte below
/// 0x20 except CR and LF (which end lines). A NUL, a tab or a stray escape inside a line is
/// dropped and the rest of the line kept, as Grbl 1.1's protocol loop does. DEL (0x7F) is not
/// among them: Grbl stores it and its parser refuses the line (error:1). Context: any.
inline bool is_discarded_control_byte(uint8_t byte) { return byte < 0x20 && byte != '\r' && byte != '\n'; }

/// Told of each realtime byte as it is read. Context: loop.
class RealtimeHandler {
 public:
  virtual void on_realtime(uint8_t byte) = 0;

 protected:
  ~RealtimeHandler() = default;
};

/// One complete line taken from the receive buffer.
struct ReceivedLine {
  static constexpr size_t kMaxLength = 127;  ///< longest line accepted (Grbl senders stay within)
  char text[kMaxLength + 1] = {};
  size_t length = 0;
  bool overflowed = false;  ///< the line was longer than kMaxLength (its text is cut; reply error:11)
};

/// The receive side of a Grbl link. pump() moves bytes from the stream into a 128-byte buffer
/// (what character-counting senders count on), handing realtime bytes over at once. When the
/// buffer is full it keeps reading only while realtime bytes come (as Grbl's receive interrupt
/// takes them out before they reach its buffer): the first other byte is held back in a
/// one-byte slot and reading stops, so the stream holds the rest (back-pressure, nothing is
/// dropped). next_line() takes one line out; CR, LF and CR LF each end one line. Control bytes
/// (is_discarded_control_byte) occupy the buffer like any other byte, as they do Grbl's, and
/// are left out of the line.
/// Context: loop only.
class GrblReceiver {
 public:
  static constexpr size_t kBufferBytes = 128;

  /// Reads what the stream has while there is room; realtime bytes go to handler.
  void pump(ByteStream& stream, RealtimeHandler& handler);
  /// Takes the next complete line, if any. Lines longer than ReceivedLine::kMaxLength are
  /// consumed whole and returned with overflowed set.
  bool next_line(ReceivedLine& line);
  /// Free bytes in the receive buffer (the second number of `Bf:`).
  size_t bytes_free() const { return kBufferBytes - count_; }
  /// Drops everything buffered (soft reset).
  void clear();

 private:
  bool has_line_end() const;
  uint8_t pop();
  static void append(ReceivedLine& line, uint8_t byte);

  uint8_t ring_[kBufferBytes] = {};
  size_t head_ = 0;   // next byte to take
  size_t count_ = 0;  // bytes held
  int held_byte_ = -1;             // a line byte read while the buffer was full, or −1
  bool skip_lf_ = false;           // a CR ended the last line: an LF right after belongs to it
  ReceivedLine partial_;           // a line longer than the buffer, being collected
  bool partial_active_ = false;
};

}  // namespace stepdance::gcode
