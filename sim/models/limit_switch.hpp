// A limit switch that closes when a machine axis reaches a set position.
#pragma once

#include <cstdint>

#include "common/sim_time.hpp"
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

/// Contact bounce of a switch closed and opened by a machine: after each change of the switch's
/// settled state at time t the line toggles in 50 µs slots, each slot's level drawn from the seed
/// and t, until t + bounce; from then on it holds the settled level. Changes are noticed when the
/// line is read, and reads must come in time order (the board reads its pins so).
class SwitchBounce {
 public:
  SwitchBounce(SimTime bounce, uint64_t seed) : bounce_(bounce), seed_(seed) {}
  /// The line's activity at `time` when the switch is settled `active`.
  bool level(SimTime time, bool active);

  static constexpr SimTime kSlot = 50 * kMicrosecond;

 private:
  SimTime bounce_;
  uint64_t seed_;
  bool known_ = false;
  bool settled_ = false;
  SimTime changed_at_ = 0;
};

}  // namespace stepdance::sim
