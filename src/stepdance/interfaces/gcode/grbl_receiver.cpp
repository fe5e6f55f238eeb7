// Receive buffer and line assembly of the Grbl link, by the rules of Grbl 1.1's protocol loop.
#include "stepdance/interfaces/gcode/grbl_receiver.hpp"

namespace stepdance::gcode {

// Loop context. Realtime bytes are taken out of the stream wherever they appear, even inside a line,
// as Grbl's serial ISR does. When the ring is full reading stops (one byte held back): the rest stays
// in the stream, so a realtime byte behind a full buffer waits, but nothing is lost.
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

// While locked after a soft-limit alarm, Grbl listens for the reset only; line bytes are dropped.
void GrblReceiver::discard(ByteStream& stream, RealtimeHandler& handler) {
  for (int value = stream.read_byte(); value >= 0; value = stream.read_byte()) {
    if (is_realtime_byte(static_cast<uint8_t>(value))) handler.on_realtime(static_cast<uint8_t>(value));
  }
}

// CR and LF both end a line (Grbl accepts either); the line framing itself is LineReader's.
bool GrblReceiver::next_line(ReceivedLine& line) {
  while (!line_.ready() && count_ > 0) {
    const uint8_t byte = ring_[head_];
    head_ = (head_ + 1) % kBufferBytes;
    --count_;
    if (byte == '\r' || byte == '\n') {
      end_line(byte);
    } else {
      assemble(byte);
    }
  }
  if (!line_.ready()) return false;
  line.text = line_.text();
  line.length = line_.length();
  line.overflowed = overflowed_ || line_.overflowed();
  return true;
}

void GrblReceiver::end_line(uint8_t byte) {
  line_.feed(byte);
  in_parentheses_ = false;
  in_semicolon_ = false;
  blank_pending_ = false;
}

void GrblReceiver::take_line() {
  line_.take();
  characters_ = 0;
  overflowed_ = false;
}

// Grbl's protocol loop cleans lines as they arrive: ( ) and ; comments removed, control characters and
// comments turned into one blank (so "G1X1(c)Y2" keeps its words apart), letters upper-cased.
void GrblReceiver::assemble(uint8_t byte) {
  if (in_parentheses_ || in_semicolon_ || overflowed_) {
    if (byte == ')') in_parentheses_ = false;  // only a `( )` comment ends before the line does
    return;
  }
  if (is_discarded_control_byte(byte)) {
    blank_pending_ = true;
  } else if (byte == '(') {
    in_parentheses_ = true;
    blank_pending_ = true;
  } else if (byte == ';') {
    in_semicolon_ = true;
  } else if (byte != '/') {  // block delete is not supported: the character is ignored
    store(byte);
  }
}

// Blanks are kept only as word separators and never inside a `$` line, where Grbl strips them (the
// `$` parser takes "$J=G1 X1" as "$J=G1X1"). A line beyond kMaxLength is answered error:11 at its end.
void GrblReceiver::store(uint8_t byte) {
  if (characters_ == ReceivedLine::kMaxLength) {
    overflowed_ = true;  // the rest of the line is thrown away; its reply is error:11
    return;
  }
  if (blank_pending_ && characters_ > 0 && line_.text()[0] != '$') line_.feed(' ');
  blank_pending_ = false;
  line_.feed((byte >= 'a' && byte <= 'z') ? static_cast<uint8_t>(byte - 'a' + 'A') : byte);
  ++characters_;
}

void GrblReceiver::clear() {
  head_ = 0;
  count_ = 0;
  held_byte_ = -1;
  line_.clear();
  take_line();
  in_parentheses_ = false;
  in_semicolon_ = false;
  blank_pending_ = false;
}

}  // namespace stepdance::gcode
