// Eibotboard replies in the EBB's two syntaxes: legacy (OK lines, mixed endings) and future.
#include "stepdance/interfaces/ebb/eibotboard.hpp"

namespace stepdance {

using ebb::EbbError;

// The two reply syntaxes (ebb-protocol.md "Framing"): legacy "OK\r\n" (or a bare "\r\n" with acks off
// by CU,1,0), future "<CMD>\n".
void Eibotboard::reply_ok() {
  if (future_syntax_) {
    send(command_name_);
    send("\n");
    return;
  }
  send(ack_enabled_ ? "OK\r\n" : "\r\n");
}

// Legacy line endings differ by command on the EBB (QM and QS end "\n\r"), hence the parameter.
void Eibotboard::reply_data(const char* data, bool ok_after, const char* legacy_ending) {
  if (future_syntax_) {
    send(command_name_);
    send(",");
    send(data);
    send("\n");
    return;
  }
  send(data);
  send(legacy_ending);
  if (ok_after) send(ack_enabled_ ? "OK\r\n" : "\r\n");
}

// The EBB's error texts and "!n" codes (ebb-protocol.md "Framing"), with the command name first in the
// future syntax. !9 (alarm) is ours: the EBB has no alarm state. An unknown command is echoed with
// its bytes in hex so an invisible character in it can be seen.
void Eibotboard::reply_error(EbbError error, const char* name, char offending) {
  ++errors_replied_;
  char storage[96];
  TextWriter line(storage, sizeof(storage));
  if (future_syntax_ && name[0] != '\0') line.text(name).character(',');
  switch (error) {
    case EbbError::kRateTooHigh: line.text("!0 Err: <axis").character(offending).text("> step rate too high"); break;
    case EbbError::kOverrun: line.text("!3 Err: RX Buffer overrun"); break;
    case EbbError::kAlarm: line.text("!9 Err: Alarm raised: motor moves refused until it is cleared"); break;
    case EbbError::kMissing: line.text("!4 Err: Missing parameter(s)"); break;
    case EbbError::kNeedComma: line.text("!5 Err: Need comma next, found: '").character(offending).text("'"); break;
    case EbbError::kInvalid: line.text("!6 Err: Invalid parameter value"); break;
    case EbbError::kExtra: line.text("!7 Err: Extra parameter"); break;
    case EbbError::kUnknownCommand: {
      static const char kHex[] = "0123456789ABCDEF";
      line.text("!8 Err: Unknown command '").text(name).character(':');
      for (const char* c = name; *c != '\0'; ++c) {
        const uint8_t byte = static_cast<uint8_t>(*c);
        line.character(kHex[byte >> 4]).character(kHex[byte & 0x0F]);
      }
      line.character('\'');
      break;
    }
    case EbbError::kNone: break;
  }
  line.text(future_syntax_ ? "\n" : "\r\n");
  send(line.c_str());
}

}  // namespace stepdance
