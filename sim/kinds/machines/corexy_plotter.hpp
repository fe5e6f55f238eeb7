// Machine kind "corexy_plotter": an AxiDraw-class CoreXY plotter on a Driver Module's sockets.
#pragma once

#include "kinds/machine_kind.hpp"
#include "models/corexy_plotter.hpp"

namespace stepdance::sim {

/// A CoreXY plotter as the scenario gives it: the model's own settings (steps_per_mm,
/// pen_down_below_us, travel and start position) and its sockets.
struct CorexyConfig : CorexySettings {
  /// Sockets of the two belt motors (steppers) and of the pen-lift servo board (required).
  char motor_a = 'A';
  char motor_b = 'B';
  char pen_servo = 'C';
};

const MachineKind& corexy_plotter_kind();

}  // namespace stepdance::sim
