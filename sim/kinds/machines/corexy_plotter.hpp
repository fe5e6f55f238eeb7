// Machine kind "corexy_plotter": an AxiDraw-class CoreXY plotter on a Driver Module's sockets.
#pragma once

#include "kinds/machine_kind.hpp"

namespace stepdance::sim {

/// A CoreXY plotter's settings.
struct CorexyConfig {
  /// Sockets of the two belt motors (steppers) and of the pen-lift servo board (required).
  char motor_a = 'A';
  char motor_b = 'B';
  char pen_servo = 'C';
  /// Motor microsteps per mm of belt.
  double steps_per_mm = 80;
  /// The pen touches the paper while the servo pulse is narrower than this (µs).
  double pen_down_below_us = 1500;
  /// Usable area from the origin (mm).
  double travel_x_mm = 300;
  double travel_y_mm = 218;
  /// Where the pen is at power-on (mm); the sketch does not know it until it homes.
  double start_x_mm = 0;
  double start_y_mm = 0;
};

const MachineKind& corexy_plotter_kind();

}  // namespace stepdance::sim
