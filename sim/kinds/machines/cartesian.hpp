// Machine kind "cartesian": an XYZE machine (a plotter with a z pen, or a printer).
#pragma once

#include <optional>

#include "kinds/machine_kind.hpp"
#include "models/cartesian_machine.hpp"

namespace stepdance::sim {

/// A cartesian machine as the scenario gives it: the model's own settings (steps_per_mm,
/// pen_down_at_or_below_mm, draw = "extruding" → draws_while_extruding; the rest keep the
/// model's defaults) and the socket of each axis. An axis without a socket stays at 0.
struct CartesianConfig : CartesianSettings {
  std::optional<char> x;
  std::optional<char> y;
  std::optional<char> z;
  std::optional<char> e;
};

const MachineKind& cartesian_kind();

}  // namespace stepdance::sim
