// Machine kind "polar": a turntable turning the paper under a pen on a radial arm.
#pragma once

#include <optional>

#include "kinds/machine_kind.hpp"

namespace stepdance::sim {

/// A polar turntable's settings.
struct PolarConfig {
  /// Sockets of the table motor and the arm motor (steppers).
  char angle = 'A';
  char radius = 'B';
  /// Optional pen-lift servo socket; without one the pen is always down.
  std::optional<char> pen_servo;
  /// Table motor microsteps per table revolution; arm motor microsteps per mm.
  double steps_per_rev = 3200;
  double steps_per_mm = 80;
  double pen_down_below_us = 1500;
};

const MachineKind& polar_turntable_kind();

}  // namespace stepdance::sim
