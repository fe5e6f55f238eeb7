// TimeBasedInterpolator: move intake and planning in the loop, profile following in the frame.
#include "stepdance/motion/time_based_interpolator.hpp"

#include <math.h>

#include "stepdance/core/fault.hpp"
#include "stepdance/hal/hal.hpp"

namespace stepdance {
namespace {

using planner::kPlannerAxes;

/// Path length the speed refers to: XYZ if they move, else |E|, else the R/T length.
// The length a speed (F) refers to, as Grbl and G-code readers expect: the XYZ distance, or for an
// extruder-only move |E|, else the R/T length. The original mixed all seven axes (incl. a virtual
// axis of length 1) into the norm, so its speeds were off for every move (original-library.md §4.9).
double path_length(const double (&delta)[kPlannerAxes]) {
  const double xyz = sqrt(delta[0] * delta[0] + delta[1] * delta[1] + delta[2] * delta[2]);
  if (xyz > 0.0) return xyz;
  if (delta[3] != 0.0) return fabs(delta[3]);
  return sqrt(delta[4] * delta[4] + delta[5] * delta[5]);
}

}  // namespace

TimeBasedInterpolator::TimeBasedInterpolator() { limits_.set_default_acceleration(kDefaultAccelerationPerS2); }

// Two stages: moves are taken and planned in the loop (look-ahead is too slow for the frame), the
// frame only follows committed profiles (docs/planner.md "What it guarantees").
Status TimeBasedInterpolator::begin() {
  for (int axis = 0; axis < kPlannerAxes; ++axis) {
    state_[axis] = 0;
    planned_end_[axis] = 0.0;
    axis_port(axis)->begin(&state_[axis], BLOCKPORT_OUTPUT, this);
  }
  output_parameter.begin(&parameter_, BLOCKPORT_OUTPUT, this);
  output_duration.begin(&duration_, BLOCKPORT_OUTPUT, this);
  const Status frame = register_in(Stage::kPreChannel);
  const Status loop_stage = register_in(Stage::kLoop);
  return frame != Status::kOk ? frame : loop_stage;
}

BlockPort* TimeBasedInterpolator::axis_port(int axis) {
  BlockPort* ports[kPlannerAxes] = {&output_x, &output_y, &output_z, &output_e, &output_r, &output_t};
  return ports[axis];
}

int16_t TimeBasedInterpolator::add_move(uint8_t mode, float velocity_per_s, DecimalPosition x, DecimalPosition y,
                                        DecimalPosition z, DecimalPosition e, DecimalPosition r, DecimalPosition t) {
  const double values[kPlannerAxes] = {x, y, z, e, r, t};
  return queue_move(mode, velocity_per_s, 0.0, values);
}

int16_t TimeBasedInterpolator::add_timed_move(uint8_t mode, float time_s, DecimalPosition x, DecimalPosition y,
                                              DecimalPosition z, DecimalPosition e, DecimalPosition r,
                                              DecimalPosition t) {
  const double values[kPlannerAxes] = {x, y, z, e, r, t};
  return queue_move(mode, 0.0, time_s, values);
}

// The original's raw interface (original-library.md §4.9): returns free slots, or −1 when full (the
// caller retries).
int16_t TimeBasedInterpolator::add_block(motion_block* block) {
  if (block == nullptr) return refuse("null block");
  const position& p = block->block_position;
  const double values[kPlannerAxes] = {p.x_mm, p.y_mm, p.z_mm, p.e_mm, p.r_mm, p.t_rad};
  return queue_move(block->block_type, block->block_velocity_per_s, block->block_time_s, values);
}

int16_t TimeBasedInterpolator::refuse(const char* why) {
  ++refused_;
  report_fault(FaultLevel::kWarning, FaultReason::kRefused, "tbi", why);
  return -1;
}

// Loop context. A full queue is back-pressure (−1, retry), everything else wrong is refused and
// reported, so nothing accepted is ever dropped. Targets are resolved against the planned end (not
// the machine's current position), so a burst of incremental moves adds up exactly. GLOBAL adopts the
// downstream position first (deep pull), as the original did, but only when idle: mid-path the planned
// end is the truth. A timed move that the axis limits cannot honour is slowed and reported, never
// driven beyond the limits. A move of zero length with a time is a dwell; without one, nothing.
int16_t TimeBasedInterpolator::queue_move(uint8_t mode, double velocity, double time_s,
                                          const double (&values)[kPlannerAxes]) {
  if (planner_.full()) return -1;  // the caller retries: back-pressure, not an error
  if (stop_pending_) return refuse("move while stopping");
  if (alarm_active()) return refuse("move during alarm");
  for (double value : values) {
    if (!isfinite(value)) return refuse("non-finite target");
  }
  if (!isfinite(velocity) || !isfinite(time_s) || time_s < 0.0) return refuse("bad speed or time");
  adopt_outputs_when_idle();
  if (mode == GLOBAL && is_idle()) {
    for (int axis = 0; axis < kPlannerAxes; ++axis) planned_end_[axis] = axis_port(axis)->pull_deep();
  }
  planner::PlannedBlock block;
  for (int axis = 0; axis < kPlannerAxes; ++axis) {
    block.end[axis] = (mode == INCREMENTAL) ? planned_end_[axis] + values[axis] : values[axis];
    block.delta[axis] = block.end[axis] - planned_end_[axis];
  }
  block.length = path_length(block.delta);
  block.id = next_id_++;
  if (block.length > 0.0) {
    const double requested = time_s > 0.0 ? block.length / time_s : fabs(velocity);
    if (!(requested > 0.0)) return refuse("move without speed or time");
    const double limit = limits_.max_speed(block.delta, block.length);
    block.cruise_speed = requested < limit ? requested : limit;
    if (time_s > 0.0 && requested > limit) {
      report_fault(FaultLevel::kWarning, FaultReason::kPlanner, "tbi", "timed move slowed by speed limits");
    }
    block.acceleration = limits_.max_acceleration(block.delta, block.length);
    block.requested_duration_s = time_s;
  } else if (time_s > 0.0) {
    block.dwell_s = time_s;
  } else {
    return static_cast<int16_t>(planner_.free_slots());  // goes nowhere: nothing to do
  }
  if (planner_.size() == 0) oldest_waiting_since_us_ = hal::micros_now();
  if (planner_.add(block) != Status::kOk) return -1;
  for (int axis = 0; axis < kPlannerAxes; ++axis) planned_end_[axis] = block.end[axis];
  commit_final_blocks();
  return static_cast<int16_t>(slots_remaining);
}

// When idle, something else (a jog, a deep reset) may have moved the outputs; planning from the old end
// would produce a jump.
void TimeBasedInterpolator::adopt_outputs_when_idle() {
  if (!is_idle()) return;
  for (int axis = 0; axis < kPlannerAxes; ++axis) planned_end_[axis] = axis_port(axis)->read_absolute();
}

// The look-ahead trade-off: a block handed to the frame can no longer be re-planned, so blocks wait in
// the loop as long as the frame has enough committed motion ahead (kCommitAheadUs), which lets later
// moves raise their junction speeds.
bool TimeBasedInterpolator::must_commit_now() {
  if (planner_.full()) return true;  // the look-ahead cannot grow: waiting gains nothing
  const uint32_t now_us = hal::micros_now();
  const bool frame_busy = !committed_.empty() || !executor_.idle();
  if (!frame_busy) {
    // Starting from rest: give a burst of moves a moment to arrive, so the first one is planned
    // with its successors instead of stopping at its end.
    return now_us - oldest_waiting_since_us_ >= kStartDelayUs;
  }
  // Running: commit early only when the frame is about to run out. The last waiting block is
  // kept until the very end, since it must be planned to stop and a follower may still come.
  const int32_t ahead_us = static_cast<int32_t>(committed_until_us_ - now_us);
  const uint32_t threshold_us = planner_.size() > 1 ? kCommitAheadUs : kLastBlockAheadUs;
  return ahead_us < static_cast<int32_t>(threshold_us);
}

// Hands final blocks to the frame through a single-producer queue (loop → frame), and keeps a clock of
// how far ahead the frame is supplied.
void TimeBasedInterpolator::commit_final_blocks() {
  while (!committed_.full()) {
    planner::PlannedBlock block;
    if (!planner_.take_final(block, must_commit_now())) break;
    const uint32_t now_us = hal::micros_now();
    if (committed_.empty() && executor_.idle()) committed_until_us_ = now_us;
    // A block longer than kMaxCommitAheadUs (a far target at a low speed) counts as that long:
    // the commit clock only needs to know the frame has plenty ahead, and the µs count must fit.
    const double block_us = planner::block_time_s(block) * 1e6;
    committed_until_us_ += block_us < kMaxCommitAheadUs ? static_cast<uint32_t>(block_us) : kMaxCommitAheadUs;
    committed_.push(block);  // cannot fail: checked not full, and only this context pushes
    oldest_waiting_since_us_ = now_us;
  }
  slots_remaining = static_cast<uint16_t>(planner_.free_slots());
}

bool TimeBasedInterpolator::is_idle() {
  return planner_.size() == 0 && committed_.empty() && executor_.idle() && !stop_pending_ && !frame_stopping_;
}

bool TimeBasedInterpolator::queue_is_full() { return planner_.full(); }

// Unlike the original (which aborted the active block at once, with no deceleration), the waiting
// moves are dropped and the frame decelerates to a stop within the acceleration limits.
void TimeBasedInterpolator::reset_block_queue() {
  planner_.clear();
  slots_remaining = static_cast<uint16_t>(planner_.free_slots());
  if (commands_.push(Command::kStop) != Status::kOk) {
    report_fault(FaultLevel::kWarning, FaultReason::kQueueFull, "tbi", "stop command queue full");
    return;
  }
  stop_pending_ = true;
}

// Stops without deceleration, for Grbl's soft reset (Ctrl-X, GCodeInterface::soft_reset), which
// halts at once; steps may be lost at speed (the caller learns whether it was moving).
void TimeBasedInterpolator::emergency_stop() {
  planner_.clear();
  slots_remaining = static_cast<uint16_t>(planner_.free_slots());
  if (commands_.push(Command::kStopNow) != Status::kOk) {
    report_fault(FaultLevel::kWarning, FaultReason::kQueueFull, "tbi", "stop command queue full");
    return;
  }
  stop_pending_ = true;
}

// Loop context. During an alarm nothing waits to run after it (Grbl's behaviour: an alarm discards
// the program's motion); once a stop has finished in the frame, the outputs are adopted as the new
// planning origin.
void TimeBasedInterpolator::loop() {
  if (alarm_active()) {
    planner_.clear();  // the frame decelerates and drops what it holds
    slots_remaining = static_cast<uint16_t>(planner_.free_slots());
    return;
  }
  if (stop_pending_) {
    if (!commands_.empty() || frame_stopping_ || !executor_.idle()) return;
    stop_pending_ = false;
    adopt_outputs_when_idle();
  }
  commit_final_blocks();
}

// Frame context: commands from the loop arrive through a queue, so the loop never changes the
// executor's state while a frame runs.
void TimeBasedInterpolator::apply_commands() {
  Command command;
  while (commands_.pop(command) == Status::kOk) {
    if (command == Command::kStopNow) {
      executor_.stop_now(committed_);
      frame_stopping_ = false;
    } else {
      executor_.request_stop();
      frame_stopping_ = true;
    }
  }
  if (alarm_active() && !frame_stopping_ && !executor_.idle()) {
    executor_.request_stop();
    frame_stopping_ = true;
  }
}

// Frame context (pre-channel). The executor advances the profile by one frame, scaled by the speed
// override (feed hold sets it to 0); only the axes that moved are pushed, so an idle axis leaves its
// port to other sources. The progress (0→1) and duration outputs drive blocks such as
// WaveGenerator2D that shape a move along its length.
void TimeBasedInterpolator::run() {
  apply_commands();
  double now[kPlannerAxes];
  for (int axis = 0; axis < kPlannerAxes; ++axis) {
    now[axis] = axis_port(axis)->convert_block_to_world_units(state_[axis]);
  }
  double before[kPlannerAxes];
  for (int axis = 0; axis < kPlannerAxes; ++axis) before[axis] = now[axis];
  executor_.advance(frame_period_s(), speed_overide, committed_, now);
  if (frame_stopping_ && !executor_.stopping()) frame_stopping_ = false;
  for (int axis = 0; axis < kPlannerAxes; ++axis) {
    if (now[axis] == before[axis]) continue;
    BlockPort& port = *axis_port(axis);
    port.set(port.convert_world_to_block_units(now[axis]));
    port.push();
  }
  output_parameter.set(executor_.parameter());
  output_parameter.push();
  output_duration.set(executor_.duration_s());
  output_duration.push();
}

}  // namespace stepdance
