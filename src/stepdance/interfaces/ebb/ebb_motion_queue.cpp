// EBB motion queue: moves pushed by the loop, taken and ticked by the frame, state published back.
#include "stepdance/interfaces/ebb/ebb_motion_queue.hpp"

#include <math.h>

#include "stepdance/core/fault.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/core/text_writer.hpp"

namespace stepdance::ebb {

namespace {

constexpr int kZeroTimeMovesPerFrame = 8;  // bounds how many EM/pen entries one frame applies
constexpr const char* kWarningSource = "Eibotboard";

/// True for the moves that turn the motors (not pen, delay or enable moves).
bool moves_motors(const EbbMove& move) {
  return move.kind == EbbMove::Kind::kSteps || move.kind == EbbMove::Kind::kTime || move.kind == EbbMove::Kind::kHome;
}

/// For the output_duration port: the longer of the two axes for SM/LM, the tick count otherwise.
double duration_s(const EbbMove& move) {
  switch (move.kind) {
    case EbbMove::Kind::kSteps: return fmax(ticks_to_cover(move, 0), ticks_to_cover(move, 1)) / kTicksPerSecond;
    case EbbMove::Kind::kHome: return 0.0;  // known only when it starts
    default: return static_cast<double>(move.ticks) / kTicksPerSecond;
  }
}

}  // namespace

// ---- loop side ------------------------------------------------------------------------------------

// The FIFO depth a client sees is CU,4's (1 by default, as on the EBB: one move executing and one
// waiting), up to kCapacity. The command name travels with the move for the stretch warning.
bool EbbMotionQueue::push(const EbbMove& move, const char* command) {
  EbbMove named = move;
  named.command[0] = command[0];
  named.command[1] = command[0] != '\0' ? command[1] : '\0';
  if (waiting() >= depth_ || fifo_.push(named) != Status::kOk) return false;
  moves_queued_ = moves_queued_ + 1;
  return true;
}

void EbbMotionQueue::control(EbbControl control) { controls_.push(control); }

void EbbMotionQueue::pen_now(uint16_t target, uint16_t rate) {
  pen_now_target_ = target;
  pen_now_rate_ = rate;
  controls_.push(EbbControl::kPenUpNow);
}

void EbbMotionQueue::reset(uint16_t servo_up) {
  depth_ = 1;
  reset_servo_ = servo_up;
  controls_.push(EbbControl::kReset);
}

// Idle means nothing queued, nothing pending from the loop, the frame not moving and the pen servo
// at its target: what a sketch waits for before taking over the outputs.
bool EbbMotionQueue::idle() const {
  return waiting() == 0 && controls_.empty() && !frame_busy_ && frame_servo_settled_;
}

// ---- frame side -----------------------------------------------------------------------------------

// The loop talks to the frame only through the queues and the published state, so no command
// changes the executor in the middle of a tick.
void EbbMotionQueue::run_frame(uint32_t period_us) {
  apply_controls();
  if (alarm_active()) stop_for_alarm();
  if (!executor_.busy()) load_next_move(period_us);
  tick(period_us);
  publish();
}

void EbbMotionQueue::tick(uint32_t period_us) {
  if (!clock_.advance(period_us)) return;
  if (executor_.tick()) {
    ++move_ticks_done_;
  } else if (!executor_.busy()) {
    move_ticks_done_ = 0;
  }
}

double EbbMotionQueue::progress() const {
  if (!executor_.busy()) return 1.0;
  const double done_s = move_ticks_done_ / static_cast<double>(kTicksPerSecond) * clock_.stretch();
  const double done = move_duration_s_ > 0.0 ? done_s / move_duration_s_ : 1.0;
  return done < 1.0 ? done : 1.0;
}

// What the loop's queries read (QM, QG, QS, QP, QE, PI, idle()).
void EbbMotionQueue::publish() {
  frame_busy_ = executor_.busy();
  frame_motor_moving_[0] = executor_.motor_moving(0);
  frame_motor_moving_[1] = executor_.motor_moving(1);
  frame_global_steps_[0] = executor_.global_steps(0);
  frame_global_steps_[1] = executor_.global_steps(1);
  frame_pen_up_ = executor_.pen_up();
  frame_servo_settled_ = executor_.servo_settled();
  frame_microstep_mode_ = executor_.microstep_mode();
  for (int motor = 0; motor < 2; ++motor) {
    const uint8_t resolution = static_cast<uint8_t>(16 >> (executor_.microstep_mode() - 1));
    frame_motor_resolution_[motor] = executor_.motor_enabled(motor) ? resolution : 0;
  }
}

// Discarded moves still count as started so the loop's queued/started difference (its FIFO depth)
// returns to zero.
void EbbMotionQueue::flush() {
  executor_.stop();
  EbbMove discard;
  while (fifo_.pop(discard) == Status::kOk) moves_started_ = moves_started_ + 1;
}

// Immediate commands (ES, CS, SP,2/3, R) bypass the FIFO, as on the EBB, through a separate queue
// the frame drains before the next tick.
void EbbMotionQueue::apply_controls() {
  EbbControl control;
  while (controls_.pop(control) == Status::kOk) {
    switch (control) {
      case EbbControl::kStop: flush(); break;
      case EbbControl::kStopDisable:
        flush();
        executor_.disable_motors();
        break;
      case EbbControl::kClearSteps: executor_.clear_global_steps(); break;
      case EbbControl::kPenUpNow: executor_.servo_now(pen_now_target_, pen_now_rate_, true); break;
      case EbbControl::kReset:
        flush();
        executor_.reset(reset_servo_);
        break;
    }
  }
}

// An alarm on the fault path stops the motors at once, as ES does (EBB moves carry no
// deceleration of their own); pen, delay and enable moves go on, so the client can still lift the pen.
void EbbMotionQueue::stop_for_alarm() {
  if (!executor_.motor_moving(0) && !executor_.motor_moving(1)) return;
  executor_.stop();
  alarm_stops_ = alarm_stops_ + 1;
}

// Zero-time entries (EM, a pen move without delay) run back to back in one frame, up to
// kZeroTimeMovesPerFrame, so a burst of them does not cost a frame each; a move that takes time is
// ticked in the same frame it is loaded. Motor moves queued before an alarm was seen are dropped.
void EbbMotionQueue::load_next_move(uint32_t period_us) {
  for (int i = 0; i < kZeroTimeMovesPerFrame; ++i) {
    EbbMove move;
    if (fifo_.pop(move) != Status::kOk) return;
    moves_started_ = moves_started_ + 1;
    if (alarm_active() && moves_motors(move)) {  // queued before the loop saw the alarm
      alarm_stops_ = alarm_stops_ + 1;
      continue;
    }
    move_ticks_done_ = 0;
    move_duration_s_ = duration_s(move);
    executor_.start(move);
    fit_to_step_rate(period_us);
    if (executor_.busy()) return;  // it takes time: tick it this frame
  }
}

// A channel steps at most once per frame: a move whose fastest motor would take more 1/16 steps
// in an EBB tick than the frames of that tick carry runs on a slower clock (EbbTickClock). The
// first such move is reported with its command and rates; every one is counted (moves_stretched,
// and on the fault path's tally).
void EbbMotionQueue::fit_to_step_rate(uint32_t period_us) {
  const double sixteenths_per_tick = executor_.peak_steps_per_tick() * executor_.sixteenths_per_step();
  if (!clock_.fit(sixteenths_per_tick, period_us)) return;
  move_duration_s_ *= clock_.stretch();
  moves_stretched_ = moves_stretched_ + 1;
  if (stretch_named_) {
    count_warning(FaultReason::kOverrun, kWarningSource);
    return;
  }
  stretch_named_ = true;
  const double carried_per_tick = EbbTickClock::carried_per_tick(period_us);
  describe_stretch(sixteenths_per_tick * kTicksPerSecond, carried_per_tick * kTicksPerSecond, period_us);
  report_fault(FaultLevel::kWarning, FaultReason::kOverrun, kWarningSource, stretch_detail_);
}

// "SM move (5000, -5000 steps) asked a motor for 41667 1/16 steps/s; the 40 us frames carry
// 25000: it ran 1.67x as long (later ones counted in moves_stretched)". Written once, then kept
// (the fault path holds the pointer). Context: frame ISR (no heap; a bounded text).
void EbbMotionQueue::describe_stretch(double asked_per_s, double carried_per_s, uint32_t period_us) {
  const EbbMove& move = executor_.move();
  TextWriter text(stretch_detail_, sizeof(stretch_detail_));
  text.character(move.command[0] != '\0' ? move.command[0] : '?').character(move.command[1]).text(" move");
  if (move.kind == EbbMove::Kind::kSteps) {
    text.text(" (").signed_number(static_cast<int32_t>(move.steps[0]) * move.direction[0]).text(", ");
    text.signed_number(static_cast<int32_t>(move.steps[1]) * move.direction[1]).text(" steps)");
  }
  text.text(" asked a motor for ").significant(asked_per_s, 6).text(" 1/16 steps/s; the ");
  text.unsigned_number(period_us).text(" us frames carry ").significant(carried_per_s, 6);
  text.text(": it ran ").fixed(clock_.stretch(), 2).text("x as long (later ones counted in moves_stretched)");
}

}  // namespace stepdance::ebb
