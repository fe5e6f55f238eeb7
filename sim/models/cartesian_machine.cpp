// CartesianMachine: per-axis steps to mm and the Z pen threshold.
#include "models/cartesian_machine.hpp"

#include <cmath>

namespace stepdance::sim {

namespace {
double axis_position_mm(const StepperDriver* driver, double steps_per_mm) {
  return driver == nullptr ? 0.0 : static_cast<double>(driver->position_steps()) / steps_per_mm;
}
}  // namespace

CartesianMachine::CartesianMachine(const CartesianDrivers& drivers, const CartesianSettings& settings)
    : Machine(settings.trace, settings.travel), drivers_(drivers), settings_(settings) {}

Machine::Sample CartesianMachine::sample(SimTime time) {
  z_mm_ = axis_position_mm(drivers_.z, settings_.z_steps_per_mm);
  e_mm_ = axis_position_mm(drivers_.e, settings_.e_steps_per_mm);
  if (e_mm_ > e_peak_mm_) {  // a retraction and its refill deposit nothing
    e_peak_mm_ = e_mm_;
    last_advance_ = time;
  }
  Sample now;
  now.pen = PenPoint{axis_position_mm(drivers_.x, settings_.x_steps_per_mm),
                     axis_position_mm(drivers_.y, settings_.y_steps_per_mm)};
  if (settings_.draws_while_extruding) {
    now.down = last_advance_.has_value() && time - *last_advance_ <= settings_.extruding_hold;
    now.shade = deposit_shade(now.pen, now.down);
  } else {
    now.down = z_mm_ <= settings_.pen_down_at_or_below_mm;
  }
  return now;
}

const char* CartesianMachine::shade_name() const {
  return settings_.draws_while_extruding ? "filament mm per toolpath mm" : "";
}

// The path is measured in chords of at least kChordMm: summing every sample's move would count
// the axes' stair steps (up to √2 too long on a diagonal), while a chord's ends are each within
// one step of the true path, so its length errs by a step at most and the errors do not add up.
std::optional<double> CartesianMachine::deposit_shade(const PenPoint& pen, bool extruding) {
  constexpr double kChordMm = 0.5;
  if (!extruding) {  // a travel move starts a new window
    chord_start_ = pen;
    window_path_mm_ = 0;
    window_start_e_mm_ = e_peak_mm_;
    return shade_;
  }
  const double chord_mm = std::hypot(pen.x_mm - chord_start_.x_mm, pen.y_mm - chord_start_.y_mm);
  if (chord_mm < kChordMm) return shade_;
  chord_start_ = pen;
  window_path_mm_ += chord_mm;
  if (window_path_mm_ >= settings_.shade_window_mm) {
    const double per_mm = (e_peak_mm_ - window_start_e_mm_) / window_path_mm_;
    shade_ = std::round(per_mm / settings_.shade_step) * settings_.shade_step;
    window_path_mm_ = 0;
    window_start_e_mm_ = e_peak_mm_;
  }
  return shade_;
}

std::optional<double> CartesianMachine::axis_mm(MachineAxis axis) const {
  if (axis == MachineAxis::kZ) return z_mm_;
  if (axis == MachineAxis::kE) return e_mm_;
  return pen_axis_mm(axis);
}

}  // namespace stepdance::sim
