// Vector2DToAngle and MoveDurationToFrequency.
#include "stepdance/motion/vector_2d_to_angle.hpp"

#include <math.h>

namespace stepdance {

Status Vector2DToAngle::begin() {
  x_ = y_ = theta_ = 0;
  input_x.begin(&x_, BLOCKPORT_INPUT, this);
  input_y.begin(&y_, BLOCKPORT_INPUT, this);
  output_theta.begin(&theta_, BLOCKPORT_OUTPUT, this);
  return register_in(Stage::kPreChannel);
}

// Frame context: the direction of this frame's motion, atan2(Δy, Δx). Unlike the original (0 when
// still), the last direction is kept, so a wave riding on the path does not snap to 0 at a stop.
void Vector2DToAngle::run() {
  input_x.pull();
  input_x.update();
  input_y.pull();
  input_y.update();
  const double dx = input_x.read(INCREMENTAL);
  const double dy = input_y.read(INCREMENTAL);
  if (dx == 0.0 && dy == 0.0) return;  // standing still: keep the last direction
  output_theta.set(output_theta.convert_world_to_block_units(atan2(dy, dx)), ABSOLUTE);
  output_theta.push();
}

Status MoveDurationToFrequency::begin() {
  duration_ = frequency_ = 0;
  input_move_duration.begin(&duration_, BLOCKPORT_INPUT, this);
  output_frequency.begin(&frequency_, BLOCKPORT_OUTPUT, this);
  return register_in(Stage::kPreChannel);
}

// round(duration × target frequency), at least 1, so each move holds a whole number of half-waves
// (original-library.md §4.11); without a duration the target frequency passes through.
void MoveDurationToFrequency::run() {
  input_move_duration.pull();
  input_move_duration.update();
  const double duration = input_move_duration.read(ABSOLUTE);
  const double target = target_frequency;
  double frequency = target;
  if (duration > 0.0) {
    frequency = floor(duration * target + 0.5);
    if (frequency < 1.0) frequency = 1.0;
  }
  output_frequency.set(output_frequency.convert_world_to_block_units(frequency), ABSOLUTE);
  output_frequency.push();
}

}  // namespace stepdance
