// CircleGenerator: increments from the closed-form circle.
#include "stepdance/motion/circle_generator.hpp"

#include <math.h>

namespace stepdance {

Status CircleGenerator::begin() {
  input_state_ = x_ = y_ = 0;
  angle_.reset();
  input.begin(&input_state_, BLOCKPORT_INPUT, this);
  output_x.begin(&x_, BLOCKPORT_OUTPUT, this);
  output_y.begin(&y_, BLOCKPORT_OUTPUT, this);
  return register_in(Stage::kPreChannel);
}

// Frame context. Increments of the closed form x = r sin θ, y = r (1 − cos θ) (the original's circle,
// counter-clockwise from the start, original-library.md §4.8), taken as differences so the path
// closes exactly after every turn. θ advances by time, or by the input's change.
void CircleGenerator::run() {
  input.pull();
  input.update();
  const double before = angle_.angle();
  const double after = angle_.advance(rotational_speed_rev_per_sec, !no_input_, input);
  const double r = radius;
  const double sin_before = trig_.sine(before);  // where the last frame ended: remembered
  const double cos_before = trig_.cosine(before);
  const double dx = r * (trig_.sine(after) - sin_before);
  const double dy = r * (cos_before - trig_.cosine(after));
  output_x.set(output_x.convert_world_to_block_units(dx), INCREMENTAL);
  output_y.set(output_y.convert_world_to_block_units(dy), INCREMENTAL);
  output_x.push();
  output_y.push();
}

}  // namespace stepdance
