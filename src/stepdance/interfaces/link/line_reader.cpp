// Line assembly for the host protocols.
#include "stepdance/interfaces/link/line_reader.hpp"

namespace stepdance::link {

namespace {
constexpr uint8_t kCarriageReturn = 0x0D;
constexpr uint8_t kLineFeed = 0x0A;
}  // namespace

// The byte step shared by pump() and feed(); inlined into pump()'s loop, which carries every byte
// of a plot (the EBB's hot path: a call per byte there costs a tenth of a command's instructions).
[[gnu::always_inline]] inline bool LineReaderBase::step(uint8_t byte, const LineRules& rules) {
  const bool ends = byte == kLineFeed || (rules.cr_ends_line && byte == kCarriageReturn);
  if (ends) return end_line();
  if (rules.printable_only && (byte < 0x20 || byte > 0x7E)) return false;
  if (length_ == capacity_) {
    overflowed_ = true;
  } else {
    buffer_[length_++] = static_cast<char>(byte);
  }
  return false;
}

// Loop context. Reads no further than the end of one line: the bytes after it stay in the stream, so
// a protocol that cannot take the line yet (a full FIFO) applies back-pressure simply by not calling
// take(). The rules are copied to a local so the per-byte loop does not reload them.
bool LineReaderBase::pump(ByteStream& stream) {
  const LineRules rules = rules_;
  while (!ready_) {
    const int value = stream.read_byte();
    if (value < 0) break;
    step(static_cast<uint8_t>(value), rules);
  }
  return ready_;
}

// For protocols that pre-filter bytes themselves (Grbl's realtime bytes, its comment stripping).
bool LineReaderBase::feed(uint8_t byte) {
  if (ready_) return false;  // the caller broke the contract: keep the waiting line intact
  return step(byte, rules_);
}

// An overlong line is delivered as one line marked overflowed (its tail discarded), so the protocol
// can answer it with its own error instead of executing a truncated command. Empty lines are skipped
// only where the protocol says so (CR LF from one client is then not two commands).
bool LineReaderBase::end_line() {
  if (rules_.strip_trailing_cr && length_ > 0 && buffer_[length_ - 1] == static_cast<char>(kCarriageReturn) &&
      !overflowed_) {
    --length_;
  }
  if (rules_.skip_empty_lines && length_ == 0 && !overflowed_) return false;
  buffer_[length_] = '\0';
  if (overflowed_) ++overflows_;
  ready_ = true;
  return true;
}

void LineReaderBase::take() {
  length_ = 0;
  overflowed_ = false;
  ready_ = false;
}

void LineReaderBase::clear() { take(); }

}  // namespace stepdance::link
