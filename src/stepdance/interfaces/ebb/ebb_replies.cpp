// EBB replies: legacy and future syntax, error lines (ebb-protocol.md "Framing").
#include "stepdance/interfaces/ebb/ebb_replies.hpp"

#include "stepdance/core/text_writer.hpp"

namespace stepdance::ebb {

namespace {
constexpr char kHex[] = "0123456789ABCDEF";
}  // namespace

void EbbReplies::set_command(const char* name) {
  size_t length = 0;
  for (; length < sizeof(command_) - 1 && name[length] != '\0'; ++length) command_[length] = name[length];
  command_[length] = '\0';
}

// The two reply syntaxes (ebb-protocol.md "Framing"): legacy "OK\r\n" (or a bare "\r\n" with acks off
// by CU,1,0), future "<CMD>\n".
void EbbReplies::ok() {
  if (future_) {
    send(command_);
    send("\n");
    return;
  }
  send(acks_ ? "OK\r\n" : "\r\n");
}

// Legacy line endings differ by command on the EBB (QM and QS end "\n\r"), hence the parameter.
void EbbReplies::data(const char* data, bool ok_after, const char* legacy_ending) {
  if (future_) {
    send(command_);
    send(",");
    send(data);
    send("\n");
    return;
  }
  send(data);
  send(legacy_ending);
  if (ok_after) send(acks_ ? "OK\r\n" : "\r\n");
}

// The future syntax puts the command name first; a line without one (an overrun) has none.
void EbbReplies::error(EbbError error, char offending) {
  ++errors_;
  char storage[96];
  TextWriter line(storage, sizeof(storage));
  if (future_ && command_[0] != '\0') line.text(command_).character(',');
  error_text(error, offending, line);
  line.text(future_ ? "\n" : "\r\n");
  send(line.c_str());
}

// The EBB's error texts and "!n" codes (ebb-protocol.md "Framing"). !9 (alarm) is ours: the EBB has
// no alarm state. An unknown command is echoed with its bytes in hex so an invisible character in it
// can be seen.
void EbbReplies::error_text(EbbError error, char offending, TextWriter& line) const {
  switch (error) {
    case EbbError::kRateTooHigh: line.text("!0 Err: <axis").character(offending).text("> step rate too high"); break;
    case EbbError::kOverrun: line.text("!3 Err: RX Buffer overrun"); break;
    case EbbError::kAlarm: line.text("!9 Err: Alarm raised: motor moves refused until it is cleared"); break;
    case EbbError::kMissing: line.text("!4 Err: Missing parameter(s)"); break;
    case EbbError::kNeedComma: line.text("!5 Err: Need comma next, found: '").character(offending).text("'"); break;
    case EbbError::kInvalid: line.text("!6 Err: Invalid parameter value"); break;
    case EbbError::kExtra: line.text("!7 Err: Extra parameter"); break;
    case EbbError::kUnknownCommand:
      line.text("!8 Err: Unknown command '").text(command_).character(':');
      for (const char* c = command_; *c != '\0'; ++c) {
        const uint8_t byte = static_cast<uint8_t>(*c);
        line.character(kHex[byte >> 4]).character(kHex[byte & 0x0F]);
      }
      line.character('\'');
      break;
    case EbbError::kNone: break;
  }
}

bool EbbReplies::parameter_error(const EbbParameters& parameters) {
  if (parameters.error() == EbbError::kNone) return false;
  error(parameters.error(), parameters.offending());
  return true;
}

// CU,10: the reply is made half before and half after the switch, as on the EBB.
bool EbbReplies::switch_syntax(bool future) {
  if (!future_ && future) {
    future_ = true;
    send("\n");
    return true;
  }
  if (future_ && !future) {
    future_ = false;
    send("CU");  // the future half; the legacy ending follows (its OK only while acks are on)
    send(acks_ ? "OK\r\n" : "\r\n");
    return true;
  }
  return false;
}

void EbbReplies::reset() {
  future_ = false;
  acks_ = true;
}

}  // namespace stepdance::ebb
