// Receive buffer and line assembly of the Grbl link.
#include "stepdance/interfaces/gcode/grbl_receiver.hpp"

namespace stepdance::gcode {

void GrblReceiver::pump(ByteStream& stream, RealtimeHandler& handler) {
  if (held_byte_ >= 0) {
    if (count_ == kBufferBytes) return;
    ring_[(head_ + count_++) % kBufferBytes] = static_cast<uint8_t>(held_byte_);
    held_byte_ = -1;
  }
  for (;;) {
    const int value = stream.read_byte();
    if (value < 0) return;
    const uint8_t byte = static_cast<uint8_t>(value);
    if (is_realtime_byte(byte)) {
      handler.on_realtime(byte);
      continue;
    }
    if (count_ == kBufferBytes) {
      held_byte_ = byte;  // stop here: the stream keeps everything after it
      return;
    }
    ring_[(head_ + count_++) % kBufferBytes] = byte;
  }
}

uint8_t GrblReceiver::pop() {
  const uint8_t byte = ring_[head_];
  head_ = (head_ + 1) % kBufferBytes;
  --count_;
  return byte;
}

void GrblReceiver::append(ReceivedLine& line, uint8_t byte) {
  if (is_discarded_control_byte(byte)) return;
  if (line.length < ReceivedLine::kMaxLength) {
    line.text[line.length++] = static_cast<char>(byte);
  } else {
    line.overflowed = true;
  }
}

bool GrblReceiver::has_line_end() const {
  for (size_t i = 0; i < count_; ++i) {
    const uint8_t byte = ring_[(head_ + i) % kBufferBytes];
    if (byte == '\n' || byte == '\r') return true;
  }
  return false;
}

bool GrblReceiver::next_line(ReceivedLine& line) {
  if (skip_lf_ && count_ > 0) {
    if (ring_[head_] == '\n') pop();
    skip_lf_ = false;
  }
  // Without a line end, a full buffer can only be the start of an over-long line: move it out
  // so the buffer keeps draining.
  if (!has_line_end()) {
    if (count_ < kBufferBytes) return false;
    partial_active_ = true;
    while (count_ > 0) append(partial_, pop());
    return false;
  }
  if (partial_active_) {
    line = partial_;
  } else {
    line = ReceivedLine{};
  }
  partial_ = ReceivedLine{};
  partial_active_ = false;
  for (uint8_t byte = pop(); byte != '\n' && byte != '\r'; byte = pop()) append(line, byte);
  line.text[line.length] = '\0';
  // The byte just taken was the line end: remember a CR so a following LF is not a new line.
  const uint8_t end = ring_[(head_ + kBufferBytes - 1) % kBufferBytes];
  skip_lf_ = (end == '\r');
  if (skip_lf_ && count_ > 0 && ring_[head_] == '\n') {
    pop();
    skip_lf_ = false;
  }
  return true;
}

void GrblReceiver::clear() {
  head_ = 0;
  count_ = 0;
  held_byte_ = -1;
  skip_lf_ = false;
  partial_ = ReceivedLine{};
  partial_active_ = false;
}

}  // namespace stepdance::gcode
