// Line assembly for the host protocols.
#include "stepdance/interfaces/link/line_reader.hpp"

namespace stepdance::link {

namespace {
constexpr uint8_t kCarriageReturn = 0x0D;
constexpr uint8_t kLineFeed = 0x0A;
}  // namespace

bool LineReaderBase::pump(ByteStream& stream) {
  while (!ready_) {
    const int value = stream.read_byte();
    if (value < 0) break;
    feed(static_cast<uint8_t>(value));
  }
  return ready_;
}

bool LineReaderBase::feed(uint8_t byte) {
  if (ready_) return false;  // the caller broke the contract: keep the waiting line intact
  const bool ends = byte == kLineFeed || (rules_.cr_ends_line && byte == kCarriageReturn);
  if (ends) return end_line();
  if (rules_.printable_only && (byte < 0x20 || byte > 0x7E)) return false;
  store(byte);
  return false;
}

void LineReaderBase::store(uint8_t byte) {
  if (length_ == capacity_) {
    overflowed_ = true;
    return;
  }
  buffer_[length_++] = static_cast<char>(byte);
}

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
