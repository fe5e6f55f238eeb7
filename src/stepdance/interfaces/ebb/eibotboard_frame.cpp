// Eibotboard in the frame: controls from the loop, the FIFO executed tick by tick, the outputs.
#include <math.h>

#include "stepdance/core/fault.hpp"
#include "stepdance/core/frame_period.hpp"
#include "stepdance/core/text_writer.hpp"
#include "stepdance/interfaces/ebb/eibotboard.hpp"

namespace stepdance {

using ebb::EbbMove;

namespace {

constexpr double kServoNeutralSteps = 1500.0;  // servo-board steps (µs) at the neutral 1.5 ms
constexpr double kServoUnitsPerStep = 12.0;     // 1/12 µs per servo-board step
constexpr int kZeroTimeMovesPerFrame = 8;       // bounds how many EM/pen entries one frame applies

/// True for the moves that turn the motors (not pen, delay or enable moves).
bool moves_motors(const EbbMove& move) {
  return move.kind == EbbMove::Kind::kSteps || move.kind == EbbMove::Kind::kTime || move.kind == EbbMove::Kind::kHome;
}

}  // namespace

// Frame context (pre-channel). The loop talks to the frame only through queues (controls_, fifo_) and
// the published frame state, so no command changes the executor in the middle of a tick.
void Eibotboard::run() {
  apply_controls();
  if (alarm_active()) stop_motion_for_alarm();
  if (!executor_.busy()) load_next_move();
  tick_ebb_time();
  publish_frame_state();
  update_outputs();
}

// The EBB's own 40 µs tick, whatever our frame period: a tick when 40 µs of frames have passed
// (every frame at 40 µs, every 4th at 10 µs, 5 ticks in 8 frames at 25 µs).
void Eibotboard::tick_ebb_time() {
  const uint32_t period_us = frame_period_us();
  tick_time_q16_ += period_us * kUnstretchedQ16;
  const uint32_t tick_q16 = ebb::kTickPeriodUs * stretch_q16_;  // stretched: a longer tick
  if (tick_time_q16_ < tick_q16) return;
  tick_time_q16_ -= tick_q16;
  if (executor_.tick()) {
    ++move_ticks_done_;
  } else if (!executor_.busy()) {
    move_ticks_done_ = 0;
  }
}

// What the loop's queries read (QM, QG, QS, QP, QE, is_idle).
void Eibotboard::publish_frame_state() {
  frame_busy_ = executor_.busy();
  frame_motor_moving_[0] = executor_.motor_moving(0);
  frame_motor_moving_[1] = executor_.motor_moving(1);
  frame_global_steps_[0] = executor_.global_steps(0);
  frame_global_steps_[1] = executor_.global_steps(1);
  frame_pen_up_ = executor_.pen_up();
  frame_servo_settled_ = executor_.servo_settled();
  frame_microstep_mode_ = executor_.microstep_mode();
  for (int motor = 0; motor < 2; ++motor) {
    frame_motor_resolution_[motor] = static_cast<uint8_t>(executor_.motor_enabled(motor) ? 16 >> (executor_.microstep_mode() - 1) : 0);
  }
}

// Discarded moves still count as started so the loop's queued/started difference (its FIFO depth)
// returns to zero.
void Eibotboard::flush_fifo() {
  executor_.stop();
  EbbMove discard;
  while (fifo_.pop(discard) == Status::kOk) moves_started_ = moves_started_ + 1;
}

// Immediate commands (ES, CS, SP,2/3, R) bypass the FIFO, as on the EBB, through a separate queue
// the frame drains before the next tick.
void Eibotboard::apply_controls() {
  Control control;
  while (controls_.pop(control) == Status::kOk) {
    switch (control) {
      case Control::kStop:
        flush_fifo();
        break;
      case Control::kStopDisable:
        flush_fifo();
        executor_.disable_motors();
        break;
      case Control::kClearSteps:
        executor_.clear_global_steps();
        break;
      case Control::kPenUpNow:
        executor_.servo_now(pen_now_target_, pen_now_rate_, true);
        break;
      case Control::kReset:
        flush_fifo();
        executor_.reset(servo_up_);
        break;
    }
  }
}

// An alarm on the fault path stops the motors at once, as ES does (EBB moves carry no
// deceleration of their own); pen, delay and enable moves go on, so the client can still lift the pen.
void Eibotboard::stop_motion_for_alarm() {
  if (!executor_.motor_moving(0) && !executor_.motor_moving(1)) return;
  executor_.stop();
  alarm_stops_ = alarm_stops_ + 1;
}

// Zero-time entries (EM, a pen move without delay) run back to back in one frame, up to
// kZeroTimeMovesPerFrame, so a burst of them does not cost a frame each; a move that takes time is
// ticked in the same frame it is loaded. Motor moves queued before an alarm was seen are dropped.
void Eibotboard::load_next_move() {
  for (int i = 0; i < kZeroTimeMovesPerFrame; ++i) {
    EbbMove move;
    if (fifo_.pop(move) != Status::kOk) return;
    moves_started_ = moves_started_ + 1;
    if (alarm_active() && moves_motors(move)) {  // queued before the loop saw the alarm
      alarm_stops_ = alarm_stops_ + 1;
      continue;
    }
    move_ticks_done_ = 0;
    move_duration_s_ = move_duration_s(move);
    executor_.start(move);
    fit_move_to_step_rate();
    if (executor_.busy()) return;  // it takes time: tick it this frame
  }
}

// For the output_duration port: the longer of the two axes for SM/LM, the tick count otherwise.
double Eibotboard::move_duration_s(const EbbMove& move) const {
  switch (move.kind) {
    case EbbMove::Kind::kSteps: {
      const double ticks = fmax(ebb::ticks_to_cover(move, 0), ebb::ticks_to_cover(move, 1));
      return ticks / ebb::kTicksPerSecond;
    }
    case EbbMove::Kind::kHome:
      return 0.0;  // known only when it starts
    default:
      return static_cast<double>(move.ticks) / ebb::kTicksPerSecond;
  }
}

// A channel steps at most once per frame: a move whose fastest motor would take more 1/16 steps
// in an EBB tick than the frames of that tick carry runs on a slower clock, the whole move, so
// every motor keeps its place on the path. The first such move is reported with its command and
// rates; every one is counted (moves_stretched, and on the fault path's tally).
void Eibotboard::fit_move_to_step_rate() {
  move_stretch_ = 1.0;
  stretch_q16_ = kUnstretchedQ16;
  const double sixteenths_per_tick = executor_.peak_steps_per_tick() * executor_.sixteenths_per_step();
  const double carried_per_tick = static_cast<double>(ebb::kTickPeriodUs) / frame_period_us();
  if (sixteenths_per_tick <= carried_per_tick) return;
  stretch_q16_ = static_cast<uint32_t>(ceil(sixteenths_per_tick / carried_per_tick * kUnstretchedQ16));
  move_stretch_ = static_cast<double>(stretch_q16_) / kUnstretchedQ16;
  move_duration_s_ *= move_stretch_;
  moves_stretched_ = moves_stretched_ + 1;
  if (stretch_named_) {
    count_warning(FaultReason::kOverrun, kWarningSource);
    return;
  }
  stretch_named_ = true;
  describe_stretch(sixteenths_per_tick * ebb::kTicksPerSecond, carried_per_tick * ebb::kTicksPerSecond);
  report_fault(FaultLevel::kWarning, FaultReason::kOverrun, kWarningSource, stretch_detail_);
}

// "SM move (5000, -5000 steps) asked a motor for 41667 1/16 steps/s; the 40 us frames carry
// 25000: it ran 1.67x as long (later ones counted in moves_stretched)". Written once, then kept
// (the fault path holds the pointer). Context: frame ISR (no heap; a bounded text).
void Eibotboard::describe_stretch(double asked_per_s, double carried_per_s) {
  const EbbMove& move = executor_.move();
  TextWriter text(stretch_detail_, sizeof(stretch_detail_));
  text.character(move.command[0] != '\0' ? move.command[0] : '?').character(move.command[1]).text(" move");
  if (move.kind == EbbMove::Kind::kSteps) {
    text.text(" (").signed_number(static_cast<int32_t>(move.steps[0]) * move.direction[0]).text(", ");
    text.signed_number(static_cast<int32_t>(move.steps[1]) * move.direction[1]).text(" steps)");
  }
  text.text(" asked a motor for ").significant(asked_per_s, 6).text(" 1/16 steps/s; the ");
  text.unsigned_number(frame_period_us()).text(" us frames carry ").significant(carried_per_s, 6);
  text.text(": it ran ").fixed(move_stretch_, 2).text("x as long (later ones counted in moves_stretched)");
}

// The motor positions become world positions: CoreXY (the AxiDraw: motor1 = x + y, motor2 = x − y,
// ebb-protocol.md) inverted as x = (m1 + m2)/2, y = (m1 − m2)/2, else one motor per axis. Z is the
// servo position relative to neutral 1.5 ms (servo units of 1/12 µs). Unchanged values are not set
// again, so a deep reset downstream is not overwritten by a stale EBB position.
void Eibotboard::update_outputs() {
  const double m1 = static_cast<double>(executor_.position_sixteenths(0)) * mm_per_sixteenth_;
  const double m2 = static_cast<double>(executor_.position_sixteenths(1)) * mm_per_sixteenth_;
  const bool core_xy = kinematics_ == EBB_KINEMATICS_COREXY;
  const double values[3] = {
      core_xy ? 0.5 * (m1 + m2) : m1,
      core_xy ? 0.5 * (m1 - m2) : m2,
      (executor_.servo_position() / kServoUnitsPerStep - kServoNeutralSteps) * z_units_per_step_,
  };
  BlockPort* ports[3] = {&output_x, &output_y, &output_z};
  for (int i = 0; i < 3; ++i) {
    if (values[i] == last_output_[i]) continue;  // unchanged: leave the port (and any reset) alone
    last_output_[i] = values[i];
    ports[i]->set(ports[i]->convert_world_to_block_units(values[i]));
    ports[i]->push();
  }
  const double duration = move_duration_s_;
  const double done_s = move_ticks_done_ / static_cast<double>(ebb::kTicksPerSecond) * move_stretch_;
  const double done = duration > 0.0 ? done_s / duration : 1.0;
  output_parameter.set(executor_.busy() ? (done < 1.0 ? done : 1.0) : 1.0);
  output_parameter.push();
  output_duration.set(duration);
  output_duration.push();
}

}  // namespace stepdance
