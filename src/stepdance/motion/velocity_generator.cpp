// VelocityGenerator: one increment per frame.
#include "stepdance/motion/velocity_generator.hpp"

namespace stepdance {

Status VelocityGenerator::begin() {
  position_ = 0;
  ramp_.reset();
  output.begin(&position_, BLOCKPORT_OUTPUT, this);
  return register_in(Stage::kPreChannel);
}

// Frame context: position += speed × frame period. The speed goes through a RateRamp, so a knob
// that jumps makes the motion ramp instead of step (no ramp when its limit is 0, the default).
void VelocityGenerator::run() {
  const double step_world = ramp_.follow(static_cast<double>(speed_units_per_sec)) * frame_period_s();
  output.set(output.convert_world_to_block_units(step_world), INCREMENTAL);
  output.push();
}

}  // namespace stepdance
