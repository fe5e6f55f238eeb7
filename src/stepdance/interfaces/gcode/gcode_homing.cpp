// GCodeInterface's `$H`: runs the sketch's Homing and adopts the homed position afterwards.
#include "stepdance/homing/homing.hpp"
#include "stepdance/interfaces/gcode/gcode_interface.hpp"

namespace stepdance {

// $H runs the sketch's own Homing block (its axes, switches and order); without one, error:5 as Grbl
// answers when homing is disabled.
gcode::GrblError GCodeInterface::home() {
  if (homing_ == nullptr) return gcode::GrblError::kHomingDisabled;
  homing_->start_homing_routine();
  homing_started_ = homing_->is_homing();
  return gcode::GrblError::kOk;
}

bool GCodeInterface::homing_succeeded() { return homing_ != nullptr && homing_->is_homed(); }

// Once the routine ends, the planner's outputs take the machine position the chain now holds.
void GCodeInterface::adopt_homed_position() {
  if (!homing_started_ || homing_->is_homing()) return;
  homing_started_ = false;
  if (!homing_->is_homed()) return;
  BlockPort* const ports[] = {&output_x, &output_y, &output_z, &output_e};
  for (BlockPort* port : ports) {
    if (port->peer() != nullptr) port->pull_deep();
  }
}

}  // namespace stepdance
