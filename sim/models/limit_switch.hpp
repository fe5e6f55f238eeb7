// A limit switch that closes when a machine axis reaches a set position.
#pragma once

#include "models/machine.hpp"

namespace stepdance::sim {

/// Which side of the trip point makes the switch active.
enum class LimitSide { kBelow, kAbove };

/// Active while the watched axis is at or beyond `at_mm` on `side`: value ≤ at_mm for kBelow,
/// value ≥ at_mm for kAbove. The line level it produces is the board's concern.
class LimitSwitch {
 public:
  LimitSwitch(MachineAxis axis, double at_mm, LimitSide side = LimitSide::kBelow);

  /// Whether the switch is active with the axis at `axis_mm`.
  bool active_at(double axis_mm) const;
  /// Whether the switch is active for the machine's last update; false if it lacks the axis.
  bool active(const Machine& machine) const;

  MachineAxis axis() const { return axis_; }
  double at_mm() const { return at_mm_; }
  LimitSide side() const { return side_; }

 private:
  MachineAxis axis_;
  double at_mm_;
  LimitSide side_;
};

}  // namespace stepdance::sim
