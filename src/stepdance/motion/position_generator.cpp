// PositionGenerator: target bookkeeping in the loop, speed-limited stepping in the frame.
#include "stepdance/motion/position_generator.hpp"

#include <math.h>

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

void PositionGenerator::go(double value, PositionMode mode, double speed_units_per_s) {
  hal::CriticalSection guard;
  set_speed(speed_units_per_s);
  go(value, mode);
}

void PositionGenerator::go(double value, PositionMode mode) {
  hal::CriticalSection guard;
  follow_output_reset();
  const double value_block = output.convert_world_to_block_units(value);
  if (mode == INCREMENTAL) {
    target_ = target_ + value_block;
    return;
  }
  if (mode == GLOBAL) {
    output.pull_deep();
    last_set_ = position_;  // the adopted position is not a reset to follow
  }
  target_ = value_block;
}

double PositionGenerator::target() const {
  const double pending_shift = position_ - last_set_;  // a reset not yet seen by run()
  return output.convert_block_to_world_units(target_ + pending_shift);
}

void PositionGenerator::run() {
  follow_output_reset();
  const double position = position_;
  const double remaining = target_ - position;
  const double max_step = max_step_block_units();
  const bool arriving = fabs(remaining) <= max_step;
  const double next = arriving ? target_ : position + copysign(max_step, remaining);
  output.set(next);
  last_set_ = next;
  output.push();
}

double PositionGenerator::max_step_block_units() const {
  const double speed = fabs(static_cast<double>(speed_units_per_sec));
  return speed * kFramePeriodS / fabs(output.ratio());
}

// Someone reset the output since this block last set it: move the target by the same amount.
void PositionGenerator::follow_output_reset() {
  const double shift = position_ - last_set_;
  if (shift == 0.0) return;
  target_ = target_ + shift;
  last_set_ = position_;
}

}  // namespace stepdance
