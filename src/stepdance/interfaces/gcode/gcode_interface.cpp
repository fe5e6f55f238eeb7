// GCodeInterface: Grbl requests become planned moves; arcs are fed chord by chord as room allows.
#include "stepdance/interfaces/gcode/gcode_interface.hpp"

#include <math.h>

#include "stepdance/core/fault.hpp"
#include "stepdance/core/file_storage.hpp"
#include "stepdance/hal/hal.hpp"
#include "stepdance/hal/nonvolatile.hpp"

namespace stepdance {

using gcode::kAxisCount;
using gcode::Motion;
using gcode::MotionKind;
using gcode::MotionState;

namespace {

constexpr double kSecondsPerMinute = 60.0;
// M codes as the interpreter reports them (×10).
constexpr gcode::CommandCode kM0 = 0;
constexpr gcode::CommandCode kM3 = 30;
constexpr gcode::CommandCode kM5 = 50;

}  // namespace

// The stored settings are read when the protocol begins (the board's non-volatile store), before any
// line, so the first move already runs with the host's $110…$132.
Status GCodeInterface::begin_stream(ByteStream& stream) {
  const Status planner = interpolator_.begin();
  if (planner != Status::kOk) return planner;
  const Status own = register_in(Stage::kLoop);
  if (own != Status::kOk) return own;
  apply_settings_to_planner();
  protocol_.begin(stream, *this, &hal::nonvolatile_store());
  return Status::kOk;
}

// Loop context. Pending requests are drained before and after reading lines, so a line's motion is in
// the planner before the next line is admitted (ready_for_line). Arcs get a budget of chords per pass
// so a large arc cannot stall the loop.
void GCodeInterface::loop() {
  arc_chords_left_this_pass_ = kArcChordsPerLoopPass;
  drain_pending();
  protocol_.poll();
  drain_pending();
  if (jogging_ && interpolator_.is_idle() && pending_count_ == 0) jogging_ = false;
  adopt_homed_position();
}

// ---- requests from executed lines ----

void GCodeInterface::on_motion(const Motion& motion) {
  Pending request;
  request.kind = Pending::Kind::kMotion;
  request.motion = motion;
  push_pending(request);
}

void GCodeInterface::on_dwell(double seconds) {
  Pending request;
  request.kind = Pending::Kind::kDwell;
  request.dwell_s = seconds;
  push_pending(request);
}

void GCodeInterface::on_spindle(gcode::CommandCode m_code, double speed) {
  Pending request;
  request.kind = Pending::Kind::kSpindle;
  request.code = m_code;
  request.dwell_s = speed;
  push_pending(request);
}

// M0 is a program pause as in Grbl: a feed hold once the motion before it has finished.
void GCodeInterface::on_program_flow(gcode::CommandCode m_code) {
  if (m_code != kM0) return;  // M1 (no optional-stop switch), M2 and M30 need nothing here
  Pending request;
  request.kind = Pending::Kind::kPause;
  push_pending(request);
}

void GCodeInterface::jog(const Motion& motion) {
  Pending request;
  request.kind = Pending::Kind::kJog;
  request.motion = motion;
  jogging_ = true;
  push_pending(request);
}

void GCodeInterface::push_pending(const Pending& request) {
  // ready_for_line() admits a line only when the FIFO is empty, and a line asks for at most
  // kPendingCapacity requests, so this cannot overflow; the check keeps the invariant honest.
  if (pending_count_ == kPendingCapacity) {
    report_fault(FaultLevel::kFatal, FaultReason::kInvariant, "gcode", "pending request FIFO overflow");
    return;
  }
  pending_[(pending_head_ + pending_count_) % kPendingCapacity] = request;
  ++pending_count_;
  drain_pending();
}

// In order, each request only when the previous one is done: a dwell or spindle change after a
// motion waits for that motion to end, as Grbl synchronises them (protocol_buffer_synchronize).
void GCodeInterface::drain_pending() {
  apply_settings_to_planner();
  while (pending_count_ > 0) {
    const Pending& request = pending_[pending_head_];
    bool done = false;
    switch (request.kind) {
      case Pending::Kind::kDwell: done = dwell_done(request.dwell_s); break;
      case Pending::Kind::kSpindle:
      case Pending::Kind::kPause: done = act_when_idle(request); break;
      case Pending::Kind::kJog:
        done = queue_line_motion(request.motion, request.motion.feed_mm_per_min / kSecondsPerMinute, 0.0);
        break;
      case Pending::Kind::kMotion: {
        const Motion& motion = request.motion;
        if (motion.kind == MotionKind::kArc) {
          done = feed_arc(motion);
        } else if (motion.duration_min > 0.0) {
          done = queue_line_motion(motion, 0.0, motion.duration_min * kSecondsPerMinute);
        } else if (motion.kind == MotionKind::kRapid) {
          done = queue_line_motion(motion, -1.0, 0.0);
        } else {
          done = queue_line_motion(motion, motion.feed_mm_per_min / kSecondsPerMinute, 0.0);
        }
        break;
      }
    }
    if (!done) break;  // the planner is full: try again next loop pass
    pending_head_ = (pending_head_ + 1) % kPendingCapacity;
    --pending_count_;
  }
  answer_when_taken();
}

// The planner end of a G-code line's path: the line is answered once nothing of it is left to feed
// (no arc chords, no dwell); a spindle change or M0 waiting for the motion to stop does not hold its
// `ok` back.
void GCodeInterface::take_line_end(gcode::LineAnswer& answer) {
  line_answer_ = &answer;
  answer_when_taken();
}

void GCodeInterface::answer_when_taken() {
  if (line_answer_ == nullptr || line_in_progress()) return;
  gcode::LineAnswer* answer = line_answer_;
  line_answer_ = nullptr;
  answer->taken();
}

// Speed < 0 marks a rapid (G0): as fast as the axis limits ($110…) allow along the move, scaled by
// the rapid override. Targets are absolute machine positions, so queued moves never accumulate
// rounding.
bool GCodeInterface::queue_line_motion(const Motion& motion, double speed_mm_per_s, double time_s) {
  if (interpolator_.queue_is_full()) return false;
  const double* end = motion.end_mm;
  if (time_s > 0.0) {
    return interpolator_.add_timed_move(ABSOLUTE, static_cast<float>(time_s), end[0], end[1], end[2], end[3], 0, 0) >=
           0;
  }
  if (speed_mm_per_s < 0.0) {  // a rapid: as fast as the axis limits allow, scaled by the override
    double delta[planner::kPlannerAxes] = {};
    double length_sq = 0.0;
    for (int axis = 0; axis < kAxisCount; ++axis) {
      delta[axis] = end[axis] - interpolator_.planned_position(axis);
      if (axis < 3) length_sq += delta[axis] * delta[axis];
    }
    const double length = length_sq > 0.0 ? sqrt(length_sq) : fabs(delta[3]);
    if (length <= 0.0) return true;  // already there
    speed_mm_per_s = interpolator_.limits().max_speed(delta, length) * rapid_percent_ / 100.0;
  }
  // A refusal other than a full queue (an alarm) drops the motion, as Grbl's alarm flushes it.
  interpolator_.add_move(ABSOLUTE, static_cast<float>(speed_mm_per_s), end[0], end[1], end[2], end[3], 0, 0);
  return true;
}

// An arc becomes straight chords in the planner, fed as room and the per-pass budget allow; the
// next chord index survives between passes. Under G93 the arc's time is split evenly.
bool GCodeInterface::feed_arc(const Motion& arc) {
  const gcode::ArcSegmenter chords(arc, settings().arc_tolerance_mm());
  const uint32_t count = chords.segment_count();
  while (arc_next_chord_ < count) {
    if (arc_chords_left_this_pass_ == 0) return false;  // the rest in the next loop passes
    Motion chord = arc;
    chord.kind = MotionKind::kLinear;
    chords.point_mm(arc_next_chord_ + 1, chord.end_mm);
    const double time_s = arc.duration_min > 0.0 ? arc.duration_min * kSecondsPerMinute / count : 0.0;
    if (!queue_line_motion(chord, arc.feed_mm_per_min / kSecondsPerMinute, time_s)) return false;
    ++arc_next_chord_;
    --arc_chords_left_this_pass_;
    ++arc_chords_queued_;
  }
  arc_next_chord_ = 0;
  return true;
}

// Spindle changes and M0 wait for motion to stop (Grbl synchronises M3/M4/M5 with the planner), so
// the spindle never changes under a moving tool.
bool GCodeInterface::act_when_idle(const Pending& request) {
  if (!interpolator_.is_idle()) return false;
  if (request.kind == Pending::Kind::kPause) {
    feed_hold();  // M0: a program pause, resumed by cycle start (`~`)
  } else if (spindle_callback_ != nullptr) {
    spindle_callback_(request.code != kM5, request.code == kM3, request.dwell_s);
  }
  return true;
}

// G4 as Grbl's mc_dwell: once everything queued before it has run (protocol_buffer_synchronize),
// the time passes on the board's clock, a loop pass at a time (never a wait inside one), while
// realtime commands are served; the state is Idle meanwhile and the line's `ok` comes at the end.
bool GCodeInterface::dwell_done(double seconds) {
  const uint32_t now_us = hal::micros_now();
  if (!dwelling_) {
    if (!interpolator_.is_idle()) return false;
    dwelling_ = true;
    dwell_last_us_ = now_us;
    dwell_elapsed_us_ = 0;
  }
  dwell_elapsed_us_ += now_us - dwell_last_us_;  // wrap-safe: at most one wrap between passes
  dwell_last_us_ = now_us;
  if (static_cast<double>(dwell_elapsed_us_) < seconds * 1e6) return false;
  dwelling_ = false;
  return true;
}

// Grbl's $110–$112 (mm/min) and $120–$122 (mm/s²) per axis, $11 junction deviation. E takes X's
// limits: Grbl has no E settings. Applied every pass, so a `$` write acts from the next move.
void GCodeInterface::apply_settings_to_planner() {
  gcode::GrblSettings& grbl = settings();
  planner::MotionLimits& limits = interpolator_.limits();
  for (int axis = 0; axis < 3; ++axis) {
    limits.set_axis_limit(axis, grbl.max_rate_mm_per_min(axis) / kSecondsPerMinute, grbl.acceleration_mm_per_s2(axis));
  }
  limits.set_axis_limit(gcode::kAxisE, grbl.max_rate_mm_per_min(0) / kSecondsPerMinute, grbl.acceleration_mm_per_s2(0));
  interpolator_.set_junction_deviation(grbl.junction_deviation_mm());
}

// ---- state and realtime commands ----

// Grbl's states as the status report shows them: a hold wins over running, a jog is its own state.
MotionState GCodeInterface::motion_state() {
  // A dwell runs with the planner empty: Idle, as Grbl reports during mc_dwell.
  const bool busy = !interpolator_.is_idle() || (pending_count_ > 0 && !dwelling_);
  if (holding_) return MotionState::kHolding;
  if (homing_started_) return MotionState::kRun;
  if (!busy) return MotionState::kIdle;
  return jogging_ ? MotionState::kJog : MotionState::kRun;
}

bool GCodeInterface::hold_complete() { return interpolator_.current_speed() == 0.0; }

void GCodeInterface::position_mm(double (&out)[kAxisCount]) {
  BlockPort* ports[kAxisCount] = {&output_x, &output_y, &output_z, &output_e};
  for (int axis = 0; axis < kAxisCount; ++axis) out[axis] = ports[axis]->read_absolute();
}

double GCodeInterface::feed_now_mm_per_min() { return interpolator_.current_speed() * kSecondsPerMinute; }

// As Grbl's plan_get_block_buffer_available: the block executing and those handed to the frame
// still take their place, so `Bf:` equals `[OPT:]`'s count only when nothing is left to do.
uint16_t GCodeInterface::queue_slots_free() {
  const size_t held = interpolator_.moves_held() + static_cast<size_t>(pending_count_ - (dwelling_ ? 1 : 0));
  const size_t total = queue_slots_total();
  return static_cast<uint16_t>(held >= total ? 0 : total - held);
}

uint16_t GCodeInterface::queue_slots_total() { return planner::LookaheadPlanner::kCapacity; }

// A new line only when the last one's requests are all in the planner and it has room for three more
// moves (a G28 makes two), so a line is never half queued when the planner fills.
bool GCodeInterface::ready_for_line() {
  return pending_count_ == 0 && !interpolator_.stop_in_progress() && interpolator_.slots_remaining >= 3;
}

bool GCodeInterface::line_in_progress() const {
  for (int i = 0; i < pending_count_; ++i) {
    const Pending& request = pending_[(pending_head_ + i) % kPendingCapacity];
    if (request.kind == Pending::Kind::kMotion && request.motion.kind == MotionKind::kArc) return true;
    if (request.kind == Pending::Kind::kDwell) return true;  // its `ok` comes when it ends
  }
  return false;
}

void GCodeInterface::feed_hold() {
  holding_ = true;
  apply_override();
}

void GCodeInterface::cycle_start() {
  holding_ = false;
  apply_override();
}

// Grbl's Ctrl-X: everything stops at once, queued motion and overrides are dropped; the return says
// whether the machine was moving (ALARM:3, position possibly lost).
bool GCodeInterface::soft_reset() {
  const bool moving = interpolator_.current_speed() > 0.0;
  interpolator_.emergency_stop();
  pending_count_ = 0;
  line_answer_ = nullptr;  // the link answers the line the reset interrupts
  arc_next_chord_ = 0;
  dwelling_ = false;
  holding_ = false;
  jogging_ = false;
  feed_percent_ = rapid_percent_ = 100;
  apply_override();
  return moving;
}

// Grbl's jog cancel (0x85): decelerate to a stop and drop the rest, without an alarm.
void GCodeInterface::jog_cancel() {
  pending_count_ = 0;
  dwelling_ = false;
  interpolator_.reset_block_queue();
  answer_when_taken();  // nothing of a line is left to feed
}

void GCodeInterface::set_overrides(uint8_t feed_percent, uint8_t rapid_percent) {
  feed_percent_ = feed_percent;
  rapid_percent_ = rapid_percent;
  apply_override();
}

// Feed hold is override 0 (the planner decelerates on the path); otherwise the feed override. Rapids
// carry their override in their planned speed instead (queue_line_motion).
void GCodeInterface::apply_override() { interpolator_.speed_overide = holding_ ? 0.0 : feed_percent_ / 100.0; }

double GCodeInterface::steps_per_mm(int axis) { return settings().value(100 + static_cast<uint32_t>(axis)); }

}  // namespace stepdance
