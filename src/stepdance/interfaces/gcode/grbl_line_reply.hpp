// The reply a G-code line is owed, at the end of its path: `error:N` or `ok`.
#pragma once

#include <stdint.h>

#include "stepdance/interfaces/gcode/line_answer.hpp"
#include "stepdance/interfaces/link/reply_ring.hpp"

namespace stepdance::gcode {

/// The LineAnswer of the Grbl link: one G-code line at a time is open (handed down its path and
/// not yet answered). A refusal is written at once (the link took the line only with room for its
/// largest reply); an `ok` is written by settle(), when the machine has taken the line and the
/// ring has room, so a line still being taken (an arc's chords, a dwell) is answered later, as
/// Grbl answers once gc_execute_line returns. A line out of travel stays open unanswered: the
/// reset that ends its alarm answers it. Context: loop only.
class GrblLineReply final : public LineAnswer {
 public:
  /// `replies` must outlive the object.
  explicit GrblLineReply(link::ReplyRingBase& replies) : replies_(replies) {}

  /// A line is handed down the path: it is owed a reply from now. Context: loop.
  void open() { state_ = State::kOpen; }
  void refuse(GrblError error) override;
  void exceed_travel() override { state_ = State::kOutOfTravel; }
  void taken() override;
  /// Writes a due `ok` if it fits. True once no line is owed a reply (the link may take the
  /// next line). Context: loop.
  bool settle();
  /// True while a line is owed its reply (open, being taken, or out of travel). Context: loop.
  bool owed() const { return state_ != State::kNone; }
  /// True when the open line was found out of travel. Context: loop.
  bool out_of_travel() const { return state_ == State::kOutOfTravel; }
  /// Forgets the open line (a reset answers it itself). Context: loop.
  void clear() { state_ = State::kNone; }

 private:
  enum class State : uint8_t { kNone, kOpen, kOkDue, kOutOfTravel };

  link::ReplyRingBase& replies_;
  State state_ = State::kNone;
};

}  // namespace stepdance::gcode
