// Machine kind "polar": a turntable turning the paper under a pen on a radial arm.
#pragma once

#include <optional>

#include "kinds/machine_kind.hpp"
#include "models/polar_turntable.hpp"

namespace stepdance::sim {

/// A polar turntable as the scenario gives it: the model's own settings (steps_per_rev,
/// steps_per_mm, pen_down_below_us) and its sockets.
struct PolarConfig : PolarSettings {
  /// Sockets of the table motor and the arm motor (steppers).
  char angle = 'A';
  char radius = 'B';
  /// Optional pen-lift servo socket; without one the pen is always down.
  std::optional<char> pen_servo;
};

const MachineKind& polar_turntable_kind();

}  // namespace stepdance::sim
