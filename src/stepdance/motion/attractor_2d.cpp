// Attractor2D: a speed-limited step toward the target from the machine's deep position.
#include "stepdance/motion/attractor_2d.hpp"

#include <math.h>

namespace stepdance {

Status Attractor2D::begin() {
  x_ = y_ = 0;
  output_x.begin(&x_, BLOCKPORT_OUTPUT, this);
  output_y.begin(&y_, BLOCKPORT_OUTPUT, this);
  return register_in(Stage::kPreChannel);
}

// An incremental target is relative to where the machine is now (read through the chain), not to
// where this block last pushed.
void Attractor2D::set_target(double x, double y, PositionMode mode, double max_speed) {
  if (mode == INCREMENTAL) {
    x += output_x.read_deep();
    y += output_y.read_deep();
  }
  target_x_ = x;
  target_y_ = y;
  max_speed_ = max_speed;
}

// Frame context. Pulled toward the target by at most max_speed × frame period along the straight
// line, measured from the machine's deep position, so other sources moving the same axes are taken
// into account rather than fought. The 1e-9 guard avoids dividing by a zero distance.
void Attractor2D::run() {
  const double dx = target_x_ - output_x.read_deep();
  const double dy = target_y_ - output_y.read_deep();
  const double distance = hypot(dx, dy);
  const double reach = fabs(static_cast<double>(max_speed_)) * frame_period_s();
  const double scale = distance > reach && distance > 1e-9 ? reach / distance : 1.0;
  output_x.set(output_x.convert_world_to_block_units(dx * scale), INCREMENTAL);
  output_y.set(output_y.convert_world_to_block_units(dy * scale), INCREMENTAL);
  output_x.push();
  output_y.push();
}

}  // namespace stepdance
