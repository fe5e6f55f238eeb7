// CartesianMachine: per-axis steps to mm and the Z pen threshold.
#include "models/cartesian_machine.hpp"

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
  } else {
    now.down = z_mm_ <= settings_.pen_down_at_or_below_mm;
  }
  return now;
}

std::optional<double> CartesianMachine::axis_mm(MachineAxis axis) const {
  switch (axis) {
    case MachineAxis::kX:
      return pen_position().x_mm;
    case MachineAxis::kY:
      return pen_position().y_mm;
    case MachineAxis::kZ:
      return z_mm_;
    case MachineAxis::kE:
      return e_mm_;
  }
  return std::nullopt;
}

}  // namespace stepdance::sim
