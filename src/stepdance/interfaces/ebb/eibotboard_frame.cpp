// Eibotboard in the frame: the motion queue runs, and the motors' and servo's positions become the
// outputs.
#include "stepdance/core/frame_period.hpp"
#include "stepdance/interfaces/ebb/eibotboard.hpp"

namespace stepdance {

// Frame context (pre-channel). The loop talks to the frame only through the motion queue, so no
// command changes its executor in the middle of a tick.
void Eibotboard::run() {
  queue_.run_frame(frame_period_us());
  update_outputs();
}

// The motor positions become world positions: CoreXY (the AxiDraw: motor1 = x + y, motor2 = x − y,
// ebb-protocol.md) inverted as x = (m1 + m2)/2, y = (m1 − m2)/2, else one motor per axis. Z is the
// servo position relative to neutral 1.5 ms (servo units of 1/12 µs). Unchanged values are not set
// again, so a deep reset downstream is not overwritten by a stale EBB position.
void Eibotboard::update_outputs() {
  const ebb::EbbMotionExecutor& executor = queue_.executor();
  const double m1 = static_cast<double>(executor.position_sixteenths(0)) * mm_per_sixteenth_;
  const double m2 = static_cast<double>(executor.position_sixteenths(1)) * mm_per_sixteenth_;
  const bool core_xy = kinematics_ == EBB_KINEMATICS_COREXY;
  const double values[3] = {
      core_xy ? 0.5 * (m1 + m2) : m1,
      core_xy ? 0.5 * (m1 - m2) : m2,
      ebb::EbbPen::steps_from_neutral(executor.servo_position()) * z_units_per_step_,
  };
  BlockPort* ports[3] = {&output_x, &output_y, &output_z};
  for (int i = 0; i < 3; ++i) {
    if (values[i] == last_output_[i]) continue;  // unchanged: leave the port (and any reset) alone
    last_output_[i] = values[i];
    ports[i]->set(ports[i]->convert_world_to_block_units(values[i]));
    ports[i]->push();
  }
  output_parameter.set(queue_.progress());
  output_parameter.push();
  output_duration.set(queue_.move_duration_s());
  output_duration.push();
}

}  // namespace stepdance
