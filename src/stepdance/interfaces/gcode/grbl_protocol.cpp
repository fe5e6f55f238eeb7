// The Grbl link's main path: realtime bytes, lines, G-code execution, replies.
#include "stepdance/interfaces/gcode/grbl_protocol.hpp"

#include "stepdance/interfaces/gcode/arc_geometry.hpp"

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

// Lines are taken only while the machine can accept them (ready_for_line) and their largest reply
// fits: the sender's character-counting or send-response flow control then sees Grbl's own pacing.
void GrblProtocol::serve_lines() {
  for (int i = 0; i < kLinesPerPoll && answer_homing_when_done() && answer_line_when_taken(); ++i) {
    if (soft_limit_ != SoftLimit::kNone) return;
    if (reply_space() < kLargestReplyBytes || !machine_->ready_for_line()) return;
    ReceivedLine line;
    if (!receiver_.next_line(line)) return;
    execute_line(line);
    receiver_.take_line();
  }
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

// Grbl 1.1's order: an over-long line, an empty one, a `$` command, a lock, then G-code.
void GrblProtocol::execute_line(const ReceivedLine& line) {
  GrblError error = GrblError::kOk;
  if (line.overflowed) {
    error = GrblError::kLineOverflow;
  } else if (line.length == 0) {
    error = GrblError::kOk;  // empty or comment only: answered, for the sender's count
  } else if (line.text[0] == '$') {
    error = execute_system(line.text + 1, line.length - 1);
  } else if (alarm_ != 0 || machine_->motion_state() == MotionState::kJog) {
    error = GrblError::kLocked;
  } else {
    error = execute_gcode(line.text, line.length);
  }
  if (soft_limit_ != SoftLimit::kNone) return;  // answered by the reset that ends the alarm, as on Grbl
  if (error == GrblError::kOk) {
    // `$H` is answered when its routine ends, a line still being taken once it has been.
    if (!homing_reply_pending_ && machine_->line_in_progress()) ok_owed_ = true;
    if (!homing_reply_pending_ && !ok_owed_) send_text("ok");
  } else {
    char storage[16];
    TextWriter reply(storage, sizeof(storage));
    reply.text("error:").unsigned_number(grbl_number(error));
    send_line(reply);
  }
}

// Plan, check, commit: the whole line is checked against the soft limits before any of it runs (a G28
// with two legs, an arc by its box), so a refused line leaves no partial motion.
GrblError GrblProtocol::execute_gcode(const char* text, size_t length) {
  GcodeBlock block;
  const GrblError syntax = parse_line(text, length, block, parser_options_);
  if (syntax != GrblError::kOk) return syntax;
  const bool empty = block.words_present == 0 && block.g_groups_present == 0 && block.m_groups_present == 0;
  if (empty) return GrblError::kOk;
  sync_position_when_idle();
  LinePlan plan;
  const GrblError error = interpreter_.plan(block, plan);
  if (error != GrblError::kOk) return error;
  for (int i = 0; i < plan.motion_count; ++i) {
    if (within_travel(plan.motions[i])) continue;
    begin_soft_limit_alarm();  // nothing of the line runs, and nothing after it until a reset
    return GrblError::kOk;
  }
  interpreter_.commit(plan, check_mode_ ? nullptr : machine_);
  return GrblError::kOk;
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

bool GrblProtocol::within_travel(const Motion& motion) const {
  if (!settings_.soft_limits()) return true;
  // Machine space is [0, $130..$132] from the power-on (or homed) origin. A straight move is
  // checked at its end (it starts where the last one ended); an arc by the box it sweeps,
  // worked out in closed form, however many chords it makes.
  double low[kAxisCount];
  double high[kAxisCount];
  for (int axis = 0; axis < kAxisCount; ++axis) low[axis] = high[axis] = motion.end_mm[axis];
  if (motion.kind == MotionKind::kArc) arc_bounds_mm(motion, low, high);
  for (int axis = 0; axis < kOffsetAxisCount; ++axis) {
    if (low[axis] < 0.0 || high[axis] > settings_.max_travel_mm(axis)) return false;
  }
  return true;
}

// The interpreter's position is only refreshed when idle: while moving, the interpreter is ahead of
// the machine (it plans queued lines), and overwriting it would break relative moves.
void GrblProtocol::sync_position_when_idle() {
  if (machine_->motion_state() != MotionState::kIdle) return;
  double position[kAxisCount];
  machine_->position_mm(position);
  interpreter_.set_position_mm(position);
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

// A line whose work outlasts its parsing (an arc still being fed, a dwell) gets its ok when it is done,
// as Grbl answers after gc_execute_line returns; streaming senders count on that order.
bool GrblProtocol::send_owed_ok() {
  if (machine_->line_in_progress() || reply_space() < 4) return false;
  ok_owed_ = false;
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
  const bool line_owed = ok_owed_ || homing_reply_pending_ || soft_limit_ != SoftLimit::kNone;
  soft_limit_ = SoftLimit::kNone;
  homing_reply_pending_ = false;
  ok_owed_ = false;
  const bool was_moving = machine_->soft_reset();
  receiver_.clear();
  const CoordinateData coordinates = interpreter_.coordinate_data();
  interpreter_ = GcodeInterpreter{};
  interpreter_.set_coordinate_data(coordinates);
  check_mode_ = false;
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
