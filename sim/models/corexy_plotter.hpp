// CoreXY pen plotter (AxiDraw class): two belt motors move the pen, a servo board lifts it.
#pragma once

#include "models/machine.hpp"
#include "models/servo_board.hpp"
#include "models/stepper_driver.hpp"

namespace stepdance::sim {

/// Settings of a CoreXY plotter (defaults: AxiDraw V3 at 1/16 microstepping).
struct CorexySettings {
  /// Motor microsteps per mm of belt.
  double steps_per_mm = 80;
  /// The pen touches the paper while the servo pulse is narrower than this (µs).
  double pen_down_below_us = 1500;
  /// Usable area from the origin (mm): [0, travel_x] × [0, travel_y].
  double travel_x_mm = 300;
  double travel_y_mm = 218;
  PenTraceSettings trace;
  /// Pen position at power-on, mm (motors at 0 steps).
  double start_x_mm = 0;
  double start_y_mm = 0;
};

/// Pen position from the motors: with a and b the motor positions in mm (steps / steps_per_mm,
/// a step counting +1 with DIR high), x = start_x − (a + b) / 2 and y = start_y − (a − b) / 2.
/// The minus signs are the real AxiDraw's, as the original library drives it: its sketches invert
/// both channels (`invert_output()`, "so that the X axis points from motor A to motor B" and "the
/// Y axis points down") and its EBB emulation feeds an EiBotBoard's positive motor steps through
/// those inverted channels, so DIR low is the EiBotBoard's positive direction. With both channels
/// inverted, the kinematics' +x and +y are the page's (+x from motor A towards motor B, +y away
/// from the long axis). docs/scenario-format.md has the table of every machine's convention.
/// The pen is down while the servo board's current pulse is narrower than pen_down_below_us.
/// A scenario's plotter always has its pen servo (`pen_servo`, socket C by default: the reader
/// requires one); built without a servo board (pen_servo null, as unit tests do), the pen is
/// always down.
class CorexyPlotter : public Machine {
 public:
  CorexyPlotter(const StepperDriver& motor_a, const StepperDriver& motor_b, ServoBoard* pen_servo,
                const CorexySettings& settings = {});

  /// x, y: the pen (mm); z: none.
  std::optional<double> axis_mm(MachineAxis axis) const override;
  /// Motor positions at the last update (mm of belt).
  double a_mm() const { return a_mm_; }
  double b_mm() const { return b_mm_; }
  const CorexySettings& settings() const { return settings_; }

 protected:
  Sample sample(SimTime time) override;

 private:
  const StepperDriver& motor_a_;
  const StepperDriver& motor_b_;
  ServoBoard* pen_servo_;
  CorexySettings settings_;
  double a_mm_ = 0;
  double b_mm_ = 0;
};

}  // namespace stepdance::sim
