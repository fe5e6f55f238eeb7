// KinematicsCoreXY: forward map each frame, inverse map for deep synchronisation.
#include "stepdance/motion/kinematics_core_xy.hpp"

namespace stepdance {
namespace {

// A port's present state in world units (pending writes are not included: they are motion
// still to come and stay motion after a deep sync).
double world_position(const BlockPort& port) { return port.convert_block_to_world_units(port.read_target()); }

}  // namespace

KinematicsCoreXY::KinematicsCoreXY() = default;

Status KinematicsCoreXY::begin() {
  input_x.begin(&position_x_, BLOCKPORT_INPUT, this);
  input_y.begin(&position_y_, BLOCKPORT_INPUT, this);
  output_a.begin(&position_a_, BLOCKPORT_OUTPUT, this);
  output_b.begin(&position_b_, BLOCKPORT_OUTPUT, this);
  return register_in(Stage::kPreChannel);
}

// Frame context. Forward map a = x + y, b = x − y (original-library.md §4.10; no 1/2 or √2 factor),
// set absolutely so rounding never accumulates.
void KinematicsCoreXY::run() {
  input_x.pull();
  input_x.update();
  input_y.pull();
  input_y.update();
  const double x = world_position(input_x);
  const double y = world_position(input_y);
  output_a.set(output_a.convert_world_to_block_units(x + y));
  output_b.set(output_b.convert_world_to_block_units(x - y));
  output_a.push();
  output_b.push();
}

// Deep push (original-library.md §3.4): the motors take the position the inputs now hold, without
// motion.
void KinematicsCoreXY::push_deep() {
  const double x = world_position(input_x);
  const double y = world_position(input_y);
  output_a.push_deep(x + y);
  output_b.push_deep(x - y);
}

void KinematicsCoreXY::pull_deep() {
  const double a = output_a.pull_deep();
  const double b = output_b.pull_deep();
  reset_inputs_from(a, b);
}

// Inverse map x = (a + b)/2, y = (a − b)/2 from the motors' deep positions.
double KinematicsCoreXY::read_deep(BlockPort& port) {
  if (&port != &input_x && &port != &input_y) return port.read(ABSOLUTE);
  const double a = output_a.read_deep();
  const double b = output_b.read_deep();
  return &port == &input_x ? (a + b) / 2.0 : (a - b) / 2.0;
}

void KinematicsCoreXY::reset_inputs_from(double a_world, double b_world) {
  input_x.reset((a_world + b_world) / 2.0);
  input_y.reset((a_world - b_world) / 2.0);
}

}  // namespace stepdance
