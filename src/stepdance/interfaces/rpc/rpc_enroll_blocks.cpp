// The RPC names each block class enrolls, as the original library exposes them.
#include "stepdance/interfaces/rpc/rpc.hpp"
#include "stepdance/io/encoder.hpp"
#include "stepdance/motion/kinematics_core_xy.hpp"
#include "stepdance/motion/position_generator.hpp"
#include "stepdance/motion/time_based_interpolator.hpp"

namespace stepdance {

void TimeBasedInterpolator::enroll_names(RPC* rpc, const char* name) {
  rpc->enroll(name, "add_move", *this, &TimeBasedInterpolator::add_move);
  rpc->enroll(name, "add_timed_move", *this, &TimeBasedInterpolator::add_timed_move);
  rpc->enroll(name, "is_idle", *this, &TimeBasedInterpolator::is_idle);
  rpc->enroll(name, "queue_is_full", *this, &TimeBasedInterpolator::queue_is_full);
  rpc->enroll(name, "reset_block_queue", *this, &TimeBasedInterpolator::reset_block_queue);
  rpc->enroll_parameter(name, "speed_override", speed_overide);
  rpc->enroll_parameter(name, "slots_remaining", slots_remaining);
  rpc->enroll_port(name, "output_x", output_x);
  rpc->enroll_port(name, "output_y", output_y);
  rpc->enroll_port(name, "output_z", output_z);
  rpc->enroll_port(name, "output_e", output_e);
  rpc->enroll_port(name, "output_r", output_r);
  rpc->enroll_port(name, "output_t", output_t);
}

void PositionGenerator::enroll_names(RPC* rpc, const char* name) {
  rpc->enroll(name, "set_speed", *this, &PositionGenerator::set_speed);
  Status (PositionGenerator::*go_with_speed)(double, PositionMode, double) = &PositionGenerator::go;
  rpc->enroll(name, "go", *this, go_with_speed);
  rpc->enroll_parameter(name, "speed_units_per_sec", speed_units_per_sec);
  rpc->enroll_port(name, "output", output);
}

void KinematicsCoreXY::enroll_names(RPC* rpc, const char* name) {
  rpc->enroll_port(name, "input_x", input_x);
  rpc->enroll_port(name, "input_y", input_y);
  rpc->enroll_port(name, "output_a", output_a);
  rpc->enroll_port(name, "output_b", output_b);
}

void Encoder::enroll_names(RPC* rpc, const char* name) {
  double (Encoder::*read_position)() const = &Encoder::read;
  rpc->enroll(name, "read", *this, read_position);
  rpc->enroll(name, "reset", *this, &Encoder::reset);
  rpc->enroll(name, "set", *this, &Encoder::set);
  rpc->enroll(name, "set_ratio", *this, &Encoder::set_ratio);
  rpc->enroll_port(name, "output", output);
}

}  // namespace stepdance
