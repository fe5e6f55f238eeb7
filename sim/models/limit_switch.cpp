// LimitSwitch: trip-point comparison against a machine axis.
#include "models/limit_switch.hpp"

namespace stepdance::sim {

LimitSwitch::LimitSwitch(MachineAxis axis, double at_mm, LimitSide side) : axis_(axis), at_mm_(at_mm), side_(side) {}

bool LimitSwitch::active_at(double axis_mm) const {
  return side_ == LimitSide::kBelow ? axis_mm <= at_mm_ : axis_mm >= at_mm_;
}

bool LimitSwitch::active(const Machine& machine) const {
  const std::optional<double> value = machine.axis_mm(axis_);
  return value && active_at(*value);
}

}  // namespace stepdance::sim
