// The Grbl link's main path: realtime bytes, lines, G-code execution, replies.
#include "stepdance/interfaces/gcode/grbl_protocol.hpp"

namespace stepdance::gcode {
namespace {

constexpr size_t kLargestReplyBytes = 640;  // `$$` and `$#` with their `ok`
constexpr size_t kStatusReportBytes = 164;  // the longest report and its line end
constexpr int kLinesPerPoll = 4;            // bounds the time one loop pass spends here
constexpr uint8_t kAlarmSoftLimit = 2;      // Grbl's "soft limit": a target outside the travel
constexpr uint8_t kAlarmHomingFailed = 9;   // Grbl's "homing fail: could not find limit switch"

}  // namespace

// The welcome line comes first, as Grbl prints it at power-up: senders wait for "Grbl 1.1h" before
// sending. Stored settings are loaded after it so their messages follow the welcome.
void GrblProtocol::begin(ByteStream& stream, GrblMachine& machine, NonvolatileStore* store) {
  stream_ = &stream;
  machine_ = &machine;
  store_ = store;
  interpreting_.begin(machine, settings_);
  report_welcome();
  load_stored_settings();
  flush_replies();
}

// Loop context, once per pass. Realtime bytes (?, !, ~, Ctrl-X, overrides) are acted on as they
// arrive, ahead of any queued line, as Grbl's serial ISR picks them out of the stream. A status
// report is sent only when it fits whole in the reply ring.
void GrblProtocol::poll() {
  if (stream_ == nullptr) return;
  flush_replies();
  if (soft_limit_ == SoftLimit::kLocked) {
    receiver_.discard(*stream_, *this);  // as Grbl's critical-event loop: only a reset is heard
  } else {
    receiver_.pump(*stream_, *this);
  }
  if (reset_requested_) soft_reset();
  if (status_requested_ && reply_space() >= kStatusReportBytes) {
    status_requested_ = false;
    report_status();
  }
  if (soft_limit_ == SoftLimit::kStopping) finish_soft_limit_stop();
  serve_lines();
  flush_replies();
}

// Lines are taken only while the machine can accept them (ready_for_line), their largest reply fits
// and the last one has its reply: the sender's character-counting or send-response flow control then
// sees Grbl's own pacing, one line at a time as Grbl's gc_execute_line runs them.
void GrblProtocol::serve_lines() {
  for (int i = 0; i < kLinesPerPoll && answer_homing_when_done() && line_reply_.settle(); ++i) {
    if (soft_limit_ != SoftLimit::kNone) return;
    if (reply_space() < kLargestReplyBytes || !machine_->ready_for_line()) return;
    ReceivedLine line;
    if (!receiver_.next_line(line)) return;
    route_line(line);
    receiver_.take_line();
    if (line_reply_.out_of_travel()) begin_soft_limit_alarm();
  }
  line_reply_.settle();
}

// Grbl 1.1's realtime commands: ? status, ! feed hold (cancels a jog instead), ~ cycle start, 0x18
// soft reset, 0x85 jog cancel, 0x84 safety door; each acts only in the states where Grbl lets it.
void GrblProtocol::on_realtime(uint8_t byte) {
  if (byte == 0x18) {
    reset_requested_ = true;
    return;
  }
  if (soft_limit_ != SoftLimit::kNone) {
    // Stopping for a soft limit: status is still answered; locked: nothing but the reset is.
    if (byte == '?' && soft_limit_ == SoftLimit::kStopping) status_requested_ = true;
    return;
  }
  switch (byte) {
    case '?': status_requested_ = true; break;
    case '!':
    case 0x84:  // safety door: we have no door input, so it acts as a feed hold
      if (machine_->motion_state() == MotionState::kJog) {
        machine_->jog_cancel();
      } else if (machine_->motion_state() == MotionState::kRun) {
        machine_->feed_hold();
      }
      break;
    case '~':
      if (machine_->motion_state() == MotionState::kHolding) machine_->cycle_start();
      break;
    case 0x85:
      if (machine_->motion_state() == MotionState::kJog) machine_->jog_cancel();
      break;
    default: handle_override(byte); break;
  }
}

// Grbl 1.1's override bytes: feed 0x90–0x94 (reset, ±10 %, ±1 %), rapid 0x95–0x97 (100/50/25 %),
// spindle 0x99–0x9D; feed and spindle clamped to Grbl's 10–200 %. The next status report carries Ov:.
void GrblProtocol::handle_override(uint8_t byte) {
  auto clamp = [](int percent) { return static_cast<uint8_t>(percent < 10 ? 10 : (percent > 200 ? 200 : percent)); };
  int feed = feed_override_percent_;
  int spindle = spindle_override_percent_;
  switch (byte) {
    case 0x90: feed = 100; break;
    case 0x91: feed += 10; break;
    case 0x92: feed -= 10; break;
    case 0x93: feed += 1; break;
    case 0x94: feed -= 1; break;
    case 0x95: rapid_override_percent_ = 100; break;
    case 0x96: rapid_override_percent_ = 50; break;
    case 0x97: rapid_override_percent_ = 25; break;
    case 0x99: spindle = 100; break;
    case 0x9A: spindle += 10; break;
    case 0x9B: spindle -= 10; break;
    case 0x9C: spindle += 1; break;
    case 0x9D: spindle -= 1; break;
    default: return;  // spindle stop and coolant toggles: nothing to switch here
  }
  feed_override_percent_ = clamp(feed);
  spindle_override_percent_ = clamp(spindle);
  machine_->set_overrides(feed_override_percent_, rapid_override_percent_);
  reports_until_overrides_ = 0;
}

// Grbl 1.1's order: an over-long line, an empty one, a `$` command, a lock, then G-code. A G-code line
// is handed down its path once (parser, interpreter, the machine's planner) and not seen here again:
// the stage that finishes with it answers through line_reply_, which serve_lines() writes out.
void GrblProtocol::route_line(const ReceivedLine& line) {
  if (line.overflowed) return answer(GrblError::kLineOverflow);
  if (line.length == 0) return answer(GrblError::kOk);  // empty or comment only: answered, for the count
  if (line.text[0] == '$') return answer(execute_system(line.text + 1, line.length - 1));
  if (alarm_ != 0 || machine_->motion_state() == MotionState::kJog) return answer(GrblError::kLocked);
  line_reply_.open();
  parsing_.take(line.text, line.length, line_reply_);
}

// The reply to a line the link answers itself (`$` commands, refusals before any G-code is read); `$H`
// is answered when its routine ends.
void GrblProtocol::answer(GrblError error) {
  if (error != GrblError::kOk) {
    char storage[16];
    TextWriter reply(storage, sizeof(storage));
    reply.text("error:").unsigned_number(grbl_number(error));
    send_line(reply);
  } else if (!homing_reply_pending_) {
    send_text("ok");
  }
}

// A target outside the travel with soft limits on: as Grbl's limits_soft_check, a moving
// machine first comes to a controlled stop (feed hold), then everything queued is dropped and
// ALARM:2 raised; the link then hears nothing but a reset, after which `$X` or `$H` unlocks.
void GrblProtocol::begin_soft_limit_alarm() {
  soft_limit_ = SoftLimit::kStopping;
  if (machine_->motion_state() == MotionState::kRun) machine_->feed_hold();
  finish_soft_limit_stop();
}

// Called each pass until the feed hold has brought the machine to rest; only then is the queue
// dropped, so the position is kept (no steps lost) and ALARM:2 needs no re-homing.
void GrblProtocol::finish_soft_limit_stop() {
  const MotionState state = machine_->motion_state();
  const bool stopped = state == MotionState::kIdle || (state == MotionState::kHolding && machine_->hold_complete());
  if (!stopped) return;
  machine_->soft_reset();  // at rest: drops the queue, position kept
  soft_limit_ = SoftLimit::kLocked;
  raise_alarm(kAlarmSoftLimit);
  send_text("[MSG:Reset to continue]");
}

// While `$H` runs no further line is read; when its routine ends the line gets its `ok`, after
// `ALARM:9` (homing failed) if an axis did not home. Returns true once no `$H` answer is owed.
bool GrblProtocol::answer_homing_when_done() {
  if (!homing_reply_pending_) return true;
  if (machine_->homing_in_progress()) return false;
  homing_reply_pending_ = false;
  if (!machine_->homing_succeeded()) raise_alarm(kAlarmHomingFailed);
  send_text("ok");
  return true;
}

// Grbl's ALARM:n line; the link then refuses G-code (error:9) until $X or $H.
void GrblProtocol::raise_alarm(uint8_t code) {
  alarm_ = code;
  char storage[16];
  TextWriter line(storage, sizeof(storage));
  line.text("ALARM:").unsigned_number(code);
  send_line(line);
}

// As Grbl: the reset aborts the line being executed (an arc being fed, a dwell, `$H`, the line
// that raised ALARM:2), whose gc_execute_line (system_execute_line) still returns STATUS_OK, so
// it gets its `ok` (after ALARM:3 if the machine was moving) before the welcome.
void GrblProtocol::soft_reset() {
  reset_requested_ = false;
  const bool line_owed = line_reply_.owed() || homing_reply_pending_ || soft_limit_ != SoftLimit::kNone;
  soft_limit_ = SoftLimit::kNone;
  homing_reply_pending_ = false;
  line_reply_.clear();
  const bool was_moving = machine_->soft_reset();
  receiver_.clear();
  interpreting_.restart();
  feed_override_percent_ = rapid_override_percent_ = spindle_override_percent_ = 100;
  status_requested_ = false;
  if (was_moving) raise_alarm(3);  // Grbl's "reset while in motion": position may be lost
  if (line_owed) send_text("ok");
  report_welcome();
  if (alarm_ != 0) send_text("[MSG:'$H'|'$X' to unlock]");
}

void GrblProtocol::send_text(const char* text) {
  char storage[96];
  TextWriter line(storage, sizeof(storage));
  line.text(text);
  send_line(line);
}

void GrblProtocol::send_line(const TextWriter& line) { replies_.send_line(line); }

void GrblProtocol::flush_replies() { replies_.flush(*stream_); }

}  // namespace stepdance::gcode
