// The RPC names of each block class, as the original library exposes them (docs/rpc.md).
#include "stepdance/interfaces/rpc/rpc.hpp"
#include "stepdance/io/encoder.hpp"
#include "stepdance/motion/channel.hpp"
#include "stepdance/motion/kinematics_core_xy.hpp"
#include "stepdance/motion/position_generator.hpp"
#include "stepdance/motion/time_based_interpolator.hpp"

namespace stepdance {

// The names follow the original library's RPC (docs/rpc.md), so its clients work unchanged; the
// parameter is spelt "speed_override" although the member keeps the original's speed_overide.
void RPC::enroll_block(const char* name, TimeBasedInterpolator& interpolator) {
  using Tbi = TimeBasedInterpolator;
  enroll(name, "add_move", interpolator, &Tbi::add_move);
  enroll(name, "add_timed_move", interpolator, &Tbi::add_timed_move);
  enroll(name, "is_idle", interpolator, &Tbi::is_idle);
  enroll(name, "queue_is_full", interpolator, &Tbi::queue_is_full);
  enroll(name, "reset_block_queue", interpolator, &Tbi::reset_block_queue);
  enroll_parameter(name, "speed_override", interpolator.speed_overide);
  enroll_parameter(name, "slots_remaining", interpolator.slots_remaining);
  enroll_port(name, "output_x", interpolator.output_x);
  enroll_port(name, "output_y", interpolator.output_y);
  enroll_port(name, "output_z", interpolator.output_z);
  enroll_port(name, "output_e", interpolator.output_e);
  enroll_port(name, "output_r", interpolator.output_r);
  enroll_port(name, "output_t", interpolator.output_t);
}

void RPC::enroll_block(const char* name, PositionGenerator& generator) {
  enroll(name, "set_speed", generator, &PositionGenerator::set_speed);
  Status (PositionGenerator::*go_with_speed)(double, PositionMode, double) = &PositionGenerator::go;
  enroll(name, "go", generator, go_with_speed);
  enroll_parameter(name, "speed_units_per_sec", generator.speed_units_per_sec);
  enroll_port(name, "output", generator.output);
}

void RPC::enroll_block(const char* name, KinematicsCoreXY& kinematics) {
  enroll_port(name, "input_x", kinematics.input_x);
  enroll_port(name, "input_y", kinematics.input_y);
  enroll_port(name, "output_a", kinematics.output_a);
  enroll_port(name, "output_b", kinematics.output_b);
}

void RPC::enroll_block(const char* name, Channel& channel) {
  enroll(name, "set_ratio", channel, &Channel::set_ratio);
  enroll(name, "set_upper_limit", channel, &Channel::set_upper_limit);
  enroll(name, "set_lower_limit", channel, &Channel::set_lower_limit);
  enroll(name, "disable_upper_limit", channel, &Channel::disable_upper_limit);
  enroll(name, "disable_lower_limit", channel, &Channel::disable_lower_limit);
  Block& block = channel;  // enable() and disable() are Block's
  enroll(name, "disable", block, &Block::disable);
  enroll(name, "enable", block, &Block::enable);
  enroll(name, "disable_filtering", channel, &Channel::disable_filtering);
  enroll(name, "enable_filtering", channel, &Channel::enable_filtering);
  enroll_parameter(name, "current_position", channel.current_position);
  enroll_port(name, "input_target_position", channel.input_target_position);
  enroll_port(name, "input_target_position2", channel.input_target_position_2);  // the original's name
}

void RPC::enroll_block(const char* name, Encoder& encoder) {
  double (Encoder::*read_position)() const = &Encoder::read;
  enroll(name, "read", encoder, read_position);
  enroll(name, "reset", encoder, &Encoder::reset);
  enroll(name, "set", encoder, &Encoder::set);
  enroll(name, "set_ratio", encoder, &Encoder::set_ratio);
  enroll_port(name, "output", encoder.output);
}

}  // namespace stepdance
