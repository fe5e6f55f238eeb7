// Cartesian XYZE machine: one motor per axis; the pen (or nozzle) writes while Z is low enough.
#pragma once

#include "models/machine.hpp"
#include "models/stepper_driver.hpp"

namespace stepdance::sim {

/// The drivers moving each axis; any may be null (that axis stays at 0).
struct CartesianDrivers {
  const StepperDriver* x = nullptr;
  const StepperDriver* y = nullptr;
  const StepperDriver* z = nullptr;
  const StepperDriver* e = nullptr;
};

/// Settings of a cartesian machine (defaults: an Ender-3 style printer).
struct CartesianSettings {
  /// Motor microsteps per mm on each axis.
  double x_steps_per_mm = 80;
  double y_steps_per_mm = 80;
  double z_steps_per_mm = 400;
  double e_steps_per_mm = 93;
  /// The pen is down while z ≤ this (mm), unless draws_while_extruding.
  double pen_down_at_or_below_mm = 0;
  /// A printer instead: the nozzle draws while the extruder has advanced within the last
  /// extruding_hold (its steps come less often than the axes').
  bool draws_while_extruding = false;
  SimTime extruding_hold = 100 * kMillisecond;
  /// A printer shades its toolpath by mm of filament deposited per mm of path, measured over
  /// each stretch of this much extruding path (mm) and rounded to shade_step (mm/mm). One
  /// extruder step is 1/e_steps_per_mm mm, so a window of w mm measures to ±1/(e_steps_per_mm·w).
  double shade_window_mm = 5;
  double shade_step = 0.0025;
  /// Usable XY area, if any (excursions are reported).
  std::optional<TravelArea> travel;
  PenTraceSettings trace;
};

/// Each axis position is its motor's steps / steps_per_mm; the pen is at (x, y) and down while
/// z ≤ pen_down_at_or_below_mm (so a machine without a Z motor always draws) — or, for a printer
/// (draws_while_extruding), while the extruder advanced within the last extruding_hold.
class CartesianMachine : public Machine {
 public:
  CartesianMachine(const CartesianDrivers& drivers, const CartesianSettings& settings = {});

  /// x, y, z in mm at the last update.
  std::optional<double> axis_mm(MachineAxis axis) const override;
  /// Extruder position (mm of filament) at the last update.
  double e_mm() const { return e_mm_; }
  double z_mm() const { return z_mm_; }
  const CartesianSettings& settings() const { return settings_; }
  /// A printer's shade: "filament mm per toolpath mm"; a plotter's: none.
  const char* shade_name() const override;

 protected:
  Sample sample(SimTime time) override;

 private:
  CartesianDrivers drivers_;
  CartesianSettings settings_;
  double z_mm_ = 0;
  double e_mm_ = 0;
  double e_peak_mm_ = 0;
  std::optional<SimTime> last_advance_;
  /// Extrusion measured over the current window of extruding path.
  std::optional<double> deposit_shade(const PenPoint& pen, bool extruding);
  PenPoint chord_start_{};
  double window_path_mm_ = 0;
  double window_start_e_mm_ = 0;
  std::optional<double> shade_;
};

}  // namespace stepdance::sim
