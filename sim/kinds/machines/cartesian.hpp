// Machine kind "cartesian": an XYZE machine (a plotter with a z pen, or a printer).
#pragma once

#include <optional>

#include "kinds/machine_kind.hpp"

namespace stepdance::sim {

/// A cartesian machine's settings. An axis without a socket stays at 0.
struct CartesianConfig {
  std::optional<char> x;
  std::optional<char> y;
  std::optional<char> z;
  std::optional<char> e;
  /// Microsteps per mm on each axis.
  double x_steps_per_mm = 80;
  double y_steps_per_mm = 80;
  double z_steps_per_mm = 400;
  double e_steps_per_mm = 93;
  /// The pen is down while z ≤ this (mm)...
  double pen_down_at_or_below_mm = 0;
  /// ...or, with draw = "extruding", while the extruder advances (a printer's toolpath).
  bool draws_while_extruding = false;
};

const MachineKind& cartesian_kind();

}  // namespace stepdance::sim
