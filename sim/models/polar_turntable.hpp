// Polar turntable: the paper turns under a pen on a radial arm.
#pragma once

#include "models/machine.hpp"
#include "models/servo_board.hpp"
#include "models/stepper_driver.hpp"

namespace stepdance::sim {

/// Settings of a polar turntable.
struct PolarSettings {
  /// Turntable motor microsteps per revolution of the table (200 × 16 by default).
  double steps_per_rev = 3200;
  /// Radial-arm motor microsteps per mm of pen travel.
  double steps_per_mm = 80;
  /// The pen touches the paper while the servo pulse is narrower than this (µs).
  double pen_down_below_us = 1500;
  PenTraceSettings trace;
};

/// The table turns by θ = 2π · angle_steps / steps_per_rev (positive = counter-clockwise seen
/// from above) and the pen sits on the arm at radius r = radius_steps / steps_per_mm from the
/// centre, along the fixed +x direction. Because the paper turns with the table, the pen draws
/// at paper coordinates (r cos(−θ), r sin(−θ)): a point the paper carries to the pen has been
/// turned by +θ from where it sits on the paper. The pen is down while the servo board's pulse
/// is narrower than pen_down_below_us; without a servo board the pen is always down.
class PolarTurntable : public Machine {
 public:
  PolarTurntable(const StepperDriver& angle_motor, const StepperDriver& radius_motor, ServoBoard* pen_servo,
                 const PolarSettings& settings = {});

  /// x: the pen's radius (mm); y and z: none.
  std::optional<double> axis_mm(MachineAxis axis) const override;
  /// Table angle (radians) and pen radius (mm) at the last update.
  double angle_rad() const { return angle_rad_; }
  double radius_mm() const { return radius_mm_; }
  const PolarSettings& settings() const { return settings_; }

 protected:
  Sample sample(SimTime time) override;

 private:
  const StepperDriver& angle_motor_;
  const StepperDriver& radius_motor_;
  ServoBoard* pen_servo_;
  PolarSettings settings_;
  double angle_rad_ = 0;
  double radius_mm_ = 0;
};

}  // namespace stepdance::sim
