// Grbl's serial receive path: a 128-byte buffer, realtime bytes picked out, lines assembled.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "stepdance/core/byte_stream.hpp"
#include "stepdance/interfaces/link/line_reader.hpp"

namespace stepdance::gcode {

/// True for the bytes Grbl acts on the moment they arrive and never stores: `?`, `!`, `~`,
/// Ctrl-X (0x18) and the extended set 0x80–0xFF (overrides, jog cancel, safety door).
/// Context: any.
inline bool is_realtime_byte(uint8_t byte) {
  return byte == '?' || byte == '!' || byte == '~' || byte == 0x18 || byte >= 0x80;
}

/// True for the bytes Grbl 1.1's protocol loop throws away while it assembles a line: the
/// space and every control byte other than CR and LF (which end lines). A NUL, a tab or a
/// stray escape inside a line is dropped and the rest of the line kept. DEL (0x7F) is not among
/// them: Grbl stores it and its parser refuses the line (error:1). Context: any.
inline bool is_discarded_control_byte(uint8_t byte) { return byte <= 0x20 && byte != '\r' && byte != '\n'; }

/// Told of each realtime byte as it is read. Context: loop.
class RealtimeHandler {
 public:
  virtual void on_realtime(uint8_t byte) = 0;

 protected:
  ~RealtimeHandler() = default;
};

/// One line as Grbl 1.1's protocol loop hands it on: letters upper-cased, `( )` and `;`
/// comments, `/`, spaces and control bytes removed. Where blanks or a comment separated two
/// characters of a G-code line one space is kept, so the parser can tell `X1 E1` (an E word)
/// from `X1E1` (an exponent, refused as Grbl refuses it); `$` lines keep none, as on Grbl.
/// Points into the receiver, valid until GrblReceiver::take_line().
struct ReceivedLine {
  /// Characters a line may hold, spaces not counted: Grbl's LINE_BUFFER_SIZE (80) less its NUL.
  static constexpr size_t kMaxLength = 79;
  const char* text = "";
  size_t length = 0;        ///< bytes in text (the kept spaces included)
  bool overflowed = false;  ///< a character beyond kMaxLength was dropped: reply error:11
};

/// The receive side of a Grbl link. pump() moves bytes from the stream into a 128-byte buffer
/// (what character-counting senders count on), handing realtime bytes over at once. When the
/// buffer is full it keeps reading only while realtime bytes come (as Grbl's receive interrupt
/// takes them out before they reach its buffer): the first other byte is held back in a
/// one-byte slot and reading stops, so the stream holds the rest (back-pressure, nothing is
/// dropped). next_line() takes bytes out of the buffer through Grbl's line rules into the link's
/// LineReader, as Grbl's main loop does: every CR and every LF ends a line (so CR LF is two
/// lines, the second empty). Context: loop only.
class GrblReceiver {
 public:
  static constexpr size_t kBufferBytes = 128;

  /// Reads what the stream has while there is room; realtime bytes go to handler.
  void pump(ByteStream& stream, RealtimeHandler& handler);
  /// Reads and throws away every non-realtime byte the stream has (a link locked until reset);
  /// realtime bytes still go to handler.
  void discard(ByteStream& stream, RealtimeHandler& handler);
  /// Assembles from the buffer until a line ends; true with the line in `line` (it stays until
  /// take_line(), and nothing more is assembled meanwhile), false when the buffer ran out first
  /// (the part read so far is kept for the next call).
  bool next_line(ReceivedLine& line);
  /// The line handed out is done with: assembly goes on.
  void take_line();
  /// Free bytes in the receive buffer (the second number of `Bf:`).
  size_t bytes_free() const { return kBufferBytes - count_; }
  /// Drops everything buffered and the line being assembled (soft reset).
  void clear();

 private:
  static constexpr link::LineRules kLineRules{true, false, false, false};  // CR or LF ends one; empty lines count

  void assemble(uint8_t byte);
  void store(uint8_t byte);
  void end_line(uint8_t byte);

  uint8_t ring_[kBufferBytes] = {};
  size_t head_ = 0;     // next byte to take
  size_t count_ = 0;    // bytes held
  int held_byte_ = -1;  // a line byte read while the buffer was full, or −1
  // Room for the characters and the one space kept between them; the count of characters
  // (Grbl's limit) is kept here, so the reader itself never overflows.
  link::LineReader<2 * ReceivedLine::kMaxLength> line_{kLineRules};
  size_t characters_ = 0;        // characters of the line so far, spaces not counted
  bool overflowed_ = false;      // a character beyond ReceivedLine::kMaxLength was dropped
  bool in_parentheses_ = false;  // inside a `( )` comment
  bool in_semicolon_ = false;    // after a `;`: the rest of the line is comment
  bool blank_pending_ = false;   // blanks or a comment since the last stored character
};

}  // namespace stepdance::gcode
