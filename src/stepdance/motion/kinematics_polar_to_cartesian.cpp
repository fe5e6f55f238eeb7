// KinematicsPolarToCartesian: forward map per frame, inverse for deep synchronisation.
#include "stepdance/motion/kinematics_polar_to_cartesian.hpp"

#include <math.h>

#include "stepdance/motion/sine_cosine.hpp"

namespace stepdance {

Status KinematicsPolarToCartesian::begin(double fixed_radius) {
  angle_ = x_ = y_ = 0;
  radius_ = 0;
  input_radius.begin(&radius_, BLOCKPORT_INPUT, this);
  input_angle.begin(&angle_, BLOCKPORT_INPUT, this);
  output_x.begin(&x_, BLOCKPORT_OUTPUT, this);
  output_y.begin(&y_, BLOCKPORT_OUTPUT, this);
  if (fixed_radius > 0.0) input_radius.reset(fixed_radius);
  return register_in(Stage::kPreChannel);
}

// Frame context: x = r cos θ, y = r sin θ, set absolutely (original-library.md §4.10).
void KinematicsPolarToCartesian::run() {
  input_radius.pull();
  input_radius.update();
  input_angle.pull();
  input_angle.update();
  const double r = input_radius.read(ABSOLUTE);
  const SineCosine angle = sine_cosine(input_angle.read(ABSOLUTE));
  output_x.set(output_x.convert_world_to_block_units(r * angle.cosine), ABSOLUTE);
  output_y.set(output_y.convert_world_to_block_units(r * angle.sine), ABSOLUTE);
  output_x.push();
  output_y.push();
}

// The inverse for deep sync: r = |(x, y)|, θ = atan2(y, x) in (−π, π].
void KinematicsPolarToCartesian::pull_deep() {
  const double x = output_x.pull_deep();
  const double y = output_y.pull_deep();
  input_radius.reset(hypot(x, y));
  input_angle.reset(atan2(y, x));
}

double KinematicsPolarToCartesian::read_deep(BlockPort& port) {
  if (&port != &input_radius && &port != &input_angle) return port.read(ABSOLUTE);
  const double x = output_x.read_deep();
  const double y = output_y.read_deep();
  return &port == &input_radius ? hypot(x, y) : atan2(y, x);
}

}  // namespace stepdance
