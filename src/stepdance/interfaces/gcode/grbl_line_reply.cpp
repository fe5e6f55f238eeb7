// Grbl's reply to a G-code line, written when the line's path has finished with it.
#include "stepdance/interfaces/gcode/grbl_line_reply.hpp"

#include "stepdance/core/text_writer.hpp"

namespace stepdance::gcode {

// Grbl reports a refused block with its status code (report_status_message): "error:N".
void GrblLineReply::refuse(GrblError error) {
  char storage[16];
  TextWriter reply(storage, sizeof(storage));
  reply.text("error:").unsigned_number(grbl_number(error));
  replies_.send_line(reply);
  state_ = State::kNone;
}

// Only a line still open can be taken: after a reset cleared it, a late call changes nothing.
void GrblLineReply::taken() {
  if (state_ == State::kOpen) state_ = State::kOkDue;
}

// "ok" and its line end are 4 bytes; with less room the `ok` waits, and so does the next line.
bool GrblLineReply::settle() {
  if (state_ == State::kOkDue && replies_.reserve(4)) {
    replies_.send("ok\r\n");
    state_ = State::kNone;
  }
  return state_ == State::kNone;
}

}  // namespace stepdance::gcode
