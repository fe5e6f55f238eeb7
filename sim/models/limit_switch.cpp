// LimitSwitch: trip-point comparison against a machine axis.
#include "models/limit_switch.hpp"

#include "models/random_stream.hpp"

namespace stepdance::sim {

LimitSwitch::LimitSwitch(MachineAxis axis, double at_mm, LimitSide side) : axis_(axis), at_mm_(at_mm), side_(side) {}

bool LimitSwitch::active_at(double axis_mm) const {
  return side_ == LimitSide::kBelow ? axis_mm <= at_mm_ : axis_mm >= at_mm_;
}

bool LimitSwitch::active(const Machine& machine) const {
  const std::optional<double> value = machine.axis_mm(axis_);
  return value && active_at(*value);
}

bool SwitchBounce::level(SimTime time, bool active) {
  if (!known_) {
    known_ = true;
    settled_ = active;
    changed_at_ = time - bounce_;
  }
  if (active != settled_) {
    settled_ = active;
    changed_at_ = time;
  }
  const SimTime since = time - changed_at_;
  if (bounce_ <= 0 || since >= bounce_) return settled_;
  const uint64_t slot = static_cast<uint64_t>(since / kSlot);
  const bool flipped = (mix_seed(seed_ ^ static_cast<uint64_t>(changed_at_), slot) & 1) != 0;
  return flipped ? !settled_ : settled_;
}

}  // namespace stepdance::sim
