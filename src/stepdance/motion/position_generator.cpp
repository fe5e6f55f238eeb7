// PositionGenerator: target bookkeeping in the loop, speed-limited stepping in the frame.
#include "stepdance/motion/position_generator.hpp"

#include <math.h>

#include "stepdance/core/fault.hpp"
#include "stepdance/hal/hal.hpp"

namespace stepdance {

PositionGenerator::PositionGenerator() = default;

Status PositionGenerator::begin() {
  position_ = 0;
  target_ = 0;
  last_set_ = 0;
  output.begin(&position_, BLOCKPORT_OUTPUT, this);
  return register_in(Stage::kPreChannel);
}

Status PositionGenerator::go(double value, PositionMode mode, double speed_units_per_s) {
  GoCommand command;
  command.value = value;
  command.mode = mode;
  command.set_speed = true;
  command.speed = speed_units_per_s;
  return queue(command);
}

Status PositionGenerator::go(double value, PositionMode mode) {
  GoCommand command;
  command.value = value;
  command.mode = mode;
  return queue(command);
}

// Loop context. go() is queued for the frame (no locking of the frame's state), and the queued target is
// tracked here so target() and an incremental go() after another one see where the machine is going.
Status PositionGenerator::queue(const GoCommand& command) {
  const double base = commands_.empty() ? frame_target_world() : queued_target_world_;
  if (commands_.push(command) != Status::kOk) {
    report_fault(FaultLevel::kWarning, FaultReason::kQueueFull, "position generator", "go() queue full");
    return Status::kFull;
  }
  if (command.set_speed) set_speed(command.speed);  // readers see the new speed at once
  queued_target_world_ = command.mode == INCREMENTAL ? base + command.value : command.value;
  return Status::kOk;
}

// Frame context. GLOBAL first adopts the downstream position (deep pull), as the original did.
void PositionGenerator::apply(const GoCommand& command) {
  if (command.set_speed) set_speed(command.speed);
  const double value_block = output.convert_world_to_block_units(command.value);
  if (command.mode == INCREMENTAL) {
    target_ = target_ + value_block;
    return;
  }
  if (command.mode == GLOBAL) {
    output.pull_deep();
    last_set_ = position_;  // the adopted position is not a reset to follow
  }
  target_ = value_block;
}

// Loop context: the frame's target plus a reset the frame has not seen yet, under a critical section
// because both change in the frame.
double PositionGenerator::frame_target_world() const {
  hal::CriticalSection guard;                          // target_ and the reset shift change in the frame
  const double pending_shift = position_ - last_set_;  // a reset not yet seen by run()
  return output.convert_block_to_world_units(target_ + pending_shift);
}

double PositionGenerator::target() const { return commands_.empty() ? frame_target_world() : queued_target_world_; }

bool PositionGenerator::is_idle() const {
  if (!commands_.empty()) return false;
  hal::CriticalSection guard;
  return last_set_ == target_;
}

// Frame context. Constant speed, no acceleration, exact arrival: steps of speed × frame period, the
// last one shortened to land on the target (original-library.md §4.8).
void PositionGenerator::run() {
  follow_output_reset();
  GoCommand command;
  while (commands_.pop(command) == Status::kOk) apply(command);
  // At rest with an incremental output, another zero change would change nothing anywhere (the
  // first one was committed and pushed, so reads of the port already say 0): skip the frame.
  const bool resting = position_ == target_ && last_set_ == target_ && output.default_mode() == INCREMENTAL;
  if (resting && at_rest_) return;
  at_rest_ = resting;
  const double position = position_;
  const double remaining = target_ - position;
  const double max_step = max_step_block_units();
  const bool arriving = fabs(remaining) <= max_step;
  const double next = arriving ? target_ : position + copysign(max_step, remaining);
  output.set(next);
  last_set_ = next;
  output.push();
}

// speed is in world units/s; one frame's worth, converted to block units.
double PositionGenerator::max_step_block_units() const {
  const double speed = fabs(static_cast<double>(speed_units_per_sec));
  return speed * frame_period_s() / fabs(output.ratio());
}

// Someone reset the output since this block last set it: move the target by the same amount.
void PositionGenerator::follow_output_reset() {
  const double shift = position_ - last_set_;
  if (shift == 0.0) return;
  target_ = target_ + shift;
  last_set_ = position_;
}

}  // namespace stepdance
