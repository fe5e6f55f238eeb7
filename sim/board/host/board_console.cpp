// BoardConsole: the receive buffer, the kept text, and the lines handed on.
#include "board/host/board_console.hpp"

namespace stepdance::sim {

size_t BoardConsole::input_room() const {
  const size_t unread = input_.size() - read_position_;
  return unread < kInputBytes ? kInputBytes - unread : 0;
}

// Keeps the newest kTextBytes, trimming in halves so the copying stays amortised.
void BoardConsole::keep_text(const uint8_t* data, size_t length) {
  text_.append(reinterpret_cast<const char*>(data), length);
  if (text_.size() <= 2 * kTextBytes) return;
  const size_t excess = text_.size() - kTextBytes;
  text_.erase(0, excess);
  text_dropped_ += excess;
}

// Lines end at '\n' ('\r' is dropped); a line reaching kLineBytes is handed on as a piece, and
// one left unfinished is handed on after kQuietNs.
size_t BoardConsole::write(const uint8_t* data, size_t length, SimTime now_ns) {
  if (bytes_listener_) bytes_listener_(data, length);
  keep_text(data, length);
  for (size_t i = 0; i < length; ++i) {
    const char c = static_cast<char>(data[i]);
    if (c == '\r') continue;
    if (c != '\n') {
      line_ += c;
      if (line_.size() >= kLineBytes) flush_line();
      continue;
    }
    if (line_listener_) line_listener_(line_);
    line_.clear();
  }
  if (!line_.empty()) scheduler_.schedule(quiet_event_, now_ns + kQuietNs);
  return length;
}

void BoardConsole::QuietEvent::fire(Event& event, Scheduler&) { static_cast<QuietEvent&>(event).owner.flush_line(); }

void BoardConsole::flush_line() {
  if (line_.empty()) return;
  if (line_listener_) line_listener_(line_);
  line_.clear();
}

int BoardConsole::read() {
  if (read_position_ >= input_.size()) return -1;
  const int byte = input_[read_position_++];
  if (read_position_ == input_.size()) {
    input_.clear();
    read_position_ = 0;
  }
  return byte;
}

}  // namespace stepdance::sim
