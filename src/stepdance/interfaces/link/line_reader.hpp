// Cutting a host protocol's byte stream into command lines.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "stepdance/core/byte_stream.hpp"

namespace stepdance::link {

/// How one protocol cuts its bytes into lines.
struct LineRules {
  /// CR ends a line as LF does (EBB); otherwise only LF ends one and CR is an ordinary byte.
  bool cr_ends_line = false;
  /// A CR just before the LF is left out of the line (RPC: "…}\r\n" and "…}\n" are the same).
  bool strip_trailing_cr = false;
  /// Lines with no bytes are passed over (EBB, RPC); CR LF and LF CR pairs then end one line.
  bool skip_empty_lines = true;
  /// Bytes outside printable ASCII (below 0x20 or above 0x7E) are left out of the line (EBB).
  bool printable_only = false;
};

/// One line at a time from a byte stream, in caller-sized storage (see LineReader<N>).
///
/// A line longer than the capacity is consumed to its end, its first bytes kept, and handed over
/// with overflowed() set so the protocol refuses it with its own error; overflows() counts them.
/// While a complete line waits for its consumer (until take()), pump() reads nothing more, so
/// the stream (and behind it the host's USB or UART flow control) keeps the rest: a protocol
/// whose queue is full simply does not take() and nothing is lost. Context: loop.
class LineReaderBase {
 public:
  LineReaderBase(const LineReaderBase&) = delete;
  LineReaderBase& operator=(const LineReaderBase&) = delete;

  /// Reads until a line is complete or the stream has nothing more; true when a line waits.
  bool pump(ByteStream& stream);
  /// Adds one byte (only while no line waits); true when it completed a line.
  bool feed(uint8_t byte);
  /// True while a complete line waits for take().
  bool ready() const { return ready_; }
  /// The waiting line, NUL-terminated, without its line end. Writable: parsers may work in place.
  char* text() { return buffer_; }
  const char* text() const { return buffer_; }
  /// Bytes in the waiting line (at most the capacity).
  size_t length() const { return length_; }
  /// True when the waiting line was longer than the capacity (its text is cut).
  bool overflowed() const { return overflowed_; }
  /// The consumer is done with the waiting line: reading resumes.
  void take();
  /// Forgets the line being read and the waiting one (a reset).
  void clear();
  /// Lines refused for length since the start.
  uint32_t overflows() const { return overflows_; }
  /// Longest line accepted, bytes.
  size_t capacity() const { return capacity_; }

 protected:
  LineReaderBase(char* buffer, size_t capacity, LineRules rules)
      : buffer_(buffer), capacity_(capacity), rules_(rules) {}
  ~LineReaderBase() = default;

 private:
  bool step(uint8_t byte, const LineRules& rules);
  bool end_line();

  char* buffer_;
  size_t capacity_;
  LineRules rules_;
  size_t length_ = 0;
  bool overflowed_ = false;
  bool ready_ = false;
  uint32_t overflows_ = 0;
};

/// A LineReaderBase with room for lines of up to N bytes.
template <size_t N>
class LineReader final : public LineReaderBase {
 public:
  explicit LineReader(LineRules rules) : LineReaderBase(storage_, N, rules) {}

 private:
  char storage_[N + 1] = {};
};

}  // namespace stepdance::link
