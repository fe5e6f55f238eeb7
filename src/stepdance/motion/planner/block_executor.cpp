// Frame-side profile following with exact block ends.
#include "stepdance/motion/planner/block_executor.hpp"

#include <math.h>

namespace stepdance::planner {
namespace {

double min2(double a, double b) { return a < b ? a : b; }
double max2(double a, double b) { return a > b ? a : b; }

}  // namespace

// Closed-form trapezoid (or triangle) duration: accelerate v0 → peak, cruise, decelerate peak → v1,
// with peak the lower of the cruise speed and the triangle's apex. It feeds the loop's commit clock
// and output_duration; the motion itself is integrated by advance_block(). Infinite acceleration:
// constant speed.
double block_time_s(const PlannedBlock& block) {
  if (block.length <= 0.0) return block.dwell_s;
  const double a = block.acceleration;
  const double v0 = block.entry_speed;
  const double v1 = block.exit_speed;
  if (!(a > 0.0) || isinf(a)) return block.length / max2(block.cruise_speed, 1e-12);
  // Peak speed if the block never cruised: v² = (2aL + v0² + v1²) / 2.
  const double peak = min2(block.cruise_speed, sqrt((2.0 * a * block.length + v0 * v0 + v1 * v1) / 2.0));
  const double up = (peak * peak - v0 * v0) / (2.0 * a);
  const double down = (peak * peak - v1 * v1) / (2.0 * a);
  const double cruise = block.length - up - down;
  return (peak - v0) / a + (peak - v1) / a + max2(cruise, 0.0) / max2(peak, 1e-12);
}

// Frame context. The block is followed from where the axes actually are, so a block starts cleanly
// even after a stop inside the previous one.
bool BlockExecutor::load(CommittedQueue& queue, const double (&position)[kPlannerAxes]) {
  if (queue.pop(block_) != Status::kOk) return false;
  active_ = true;
  travelled_ = 0.0;
  for (int axis = 0; axis < kPlannerAxes; ++axis) start_[axis] = position[axis];
  dwell_left_s_ = block_.length > 0.0 ? 0.0 : block_.dwell_s;
  duration_s_ = block_time_s(block_);
  return true;
}

// Frame context, once per frame. Time left over when a block ends inside a frame goes to the next block
// (docs/planner.md "Exact endpoints"), so a run of short blocks is not slowed by a frame each; the
// guard bounds the work per frame when many tiny blocks end in one. Negative or NaN override acts as
// 0 (no running backwards along the path). Running dry while moving is counted as an underrun.
void BlockExecutor::advance(double dt_s, double override_factor, CommittedQueue& queue,
                            double (&position)[kPlannerAxes]) {
  if (override_factor < 0.0 || isnan(override_factor)) override_factor = 0.0;
  double left_s = dt_s;
  for (int guard = 0; guard < 64 && left_s > 0.0; ++guard) {
    if (!active_) {
      if (stopping_ && speed_ <= 0.0) {  // at rest: the stop is complete
        drop_all(queue);
        return;
      }
      if (!load(queue, position)) {
        if (speed_ > 0.0) ++underruns_;
        speed_ = 0.0;
        return;
      }
    }
    left_s = advance_block(left_s, override_factor, position);
  }
}

// The speed changes by at most a·dt per frame (the acceleration limit holds frame by frame) and never
// exceeds what still allows braking to the exit speed in the distance left, so no block overshoots its
// end. The override scales cruise; the exit is scaled only down (min(override, 1)), since the next
// block was planned to enter at no more than its exit speed. A stop targets speed 0 at once. Positions
// are placed by fraction of the straight block, so every axis stays on the line.
double BlockExecutor::advance_block(double dt_s, double override_factor, double (&position)[kPlannerAxes]) {
  if (block_.length <= 0.0) {  // a dwell: time passes (at the override's pace), nothing moves
    const double used = override_factor > 0.0 ? min2(dt_s, dwell_left_s_ / override_factor) : dt_s;
    dwell_left_s_ -= used * override_factor;
    if (dwell_left_s_ <= 1e-12 || stopping_) finish_block(position);
    return dt_s - used;
  }
  const double a = block_.acceleration;
  const double remaining = block_.length - travelled_;
  const double exit_target = stopping_ ? 0.0 : block_.exit_speed * min2(override_factor, 1.0);
  const double cruise = stopping_ ? 0.0 : block_.cruise_speed * override_factor;
  double next_speed = cruise;
  if (!isinf(a)) {
    // Highest end-of-frame speed v' that still brakes to the exit speed: after moving
    // (v + v')·dt/2 the rest r' must satisfy v'² ≤ exit² + 2·a·r'. Solved for v'.
    const double c = exit_target * exit_target + 2.0 * a * remaining - a * dt_s * speed_;
    // When the end falls inside this frame the bound is below the exit speed itself; ending
    // the block at its exit speed is always allowed.
    const double braking = max2(0.5 * (-a * dt_s + sqrt(fmax(a * a * dt_s * dt_s + 4.0 * c, 0.0))), exit_target);
    const double change = a * dt_s;
    next_speed = min2(min2(cruise, braking), speed_ + change);
    next_speed = max2(next_speed, max2(speed_ - change, 0.0));
  }
  const double mean = 0.5 * (speed_ + next_speed);
  double step = mean * dt_s;
  double used_s = dt_s;
  if (step >= remaining) {
    used_s = mean > 0.0 ? remaining / mean : dt_s;
    step = remaining;
  }
  speed_ = next_speed;
  travelled_ += step;
  if (travelled_ >= block_.length) {
    finish_block(position);
    return dt_s - used_s;
  }
  place(travelled_ / block_.length, position);
  if (stopping_ && speed_ <= 0.0) active_ = false;  // stopped inside the block: abandon the rest
  return 0.0;
}

void BlockExecutor::place(double fraction, double (&position)[kPlannerAxes]) const {
  for (int axis = 0; axis < kPlannerAxes; ++axis) {
    if (block_.delta[axis] != 0.0) position[axis] = start_[axis] + block_.delta[axis] * fraction;
  }
}

// Ends exactly on the block's target (no accumulated rounding), and only on the axes the block moves.
void BlockExecutor::finish_block(double (&position)[kPlannerAxes]) {
  for (int axis = 0; axis < kPlannerAxes; ++axis) {
    if (block_.delta[axis] != 0.0) position[axis] = block_.end[axis];
  }
  active_ = false;
  ++completed_;
}

double BlockExecutor::parameter() const {
  if (!active_) return 1.0;
  if (block_.length <= 0.0) return block_.dwell_s > 0.0 ? 1.0 - dwell_left_s_ / block_.dwell_s : 1.0;
  return travelled_ / block_.length;
}

// The frame is the only consumer of the committed queue, so draining it here is safe without a lock.
void BlockExecutor::drop_all(CommittedQueue& queue) {
  PlannedBlock discard;
  while (queue.pop(discard) == Status::kOk) {
  }
  active_ = false;
  stopping_ = false;
  speed_ = 0.0;
}

void BlockExecutor::stop_now(CommittedQueue& queue) { drop_all(queue); }

}  // namespace stepdance::planner
