// ThresholdGenerator: crossings counted in the frame, callbacks run in the loop.
#include "stepdance/motion/threshold_generator.hpp"

namespace stepdance {

Status ThresholdGenerator::begin() {
  input_state_ = output_state_ = 0;
  input.begin(&input_state_, BLOCKPORT_INPUT, this);
  output.begin(&output_state_, BLOCKPORT_OUTPUT, this);
  const Status frame = register_in(Stage::kPreChannel);
  return frame != Status::kOk ? frame : register_in(Stage::kLoop);
}

void ThresholdGenerator::setUpperThreshold(double value, bool clamp) {
  upper_ = value;
  clamp_upper_ = clamp;
  has_upper_ = true;
}

void ThresholdGenerator::setLowerThreshold(double value, bool clamp) {
  lower_ = value;
  clamp_lower_ = clamp;
  has_lower_ = true;
}

// Frame context. Crossings are counted on entering the region (≥ upper, ≤ lower), not every frame the
// value stays beyond, as the original did (original-library.md §4.8): one callback per crossing.
void ThresholdGenerator::run() {
  input.pull();
  input.update();
  double value = input.read(ABSOLUTE);
  const bool above = has_upper_ && value >= upper_;
  const bool below = has_lower_ && value <= lower_;
  if (above && !was_above_) upper_crossings_ = upper_crossings_ + 1;
  if (below && !was_below_) lower_crossings_ = lower_crossings_ + 1;
  was_above_ = above;
  was_below_ = below;
  if (above && clamp_upper_) value = upper_;
  if (below && clamp_lower_) value = lower_;
  output.set(output.convert_world_to_block_units(value), ABSOLUTE);
  output.push();
}

void ThresholdGenerator::loop() {
  // Each crossing the frame counted runs its callback once, here.
  while (upper_called_ != upper_crossings_) {
    ++upper_called_;
    if (upper_callback_ != nullptr) upper_callback_();
  }
  while (lower_called_ != lower_crossings_) {
    ++lower_called_;
    if (lower_callback_ != nullptr) lower_callback_();
  }
}

}  // namespace stepdance
