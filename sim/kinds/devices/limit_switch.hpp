// Device kind "limit_switch": a switch on LIMIT_A..LIMIT_D tripped by the machine or held by a hand.
#pragma once

#include "kinds/device_kind.hpp"
#include "models/machine.hpp"

namespace stepdance::sim {

/// A limit switch's settings: active while `axis` of the machine is at or beyond `at_mm` on the
/// side `active_above` says (below by default); `bounce_ms` of contact bounce after each change.
struct LimitSwitchConfig {
  MachineAxis axis = MachineAxis::kX;
  double at_mm = 0;
  bool active_above = false;
  double bounce_ms = 0;
};

const DeviceKind& limit_switch_kind();

}  // namespace stepdance::sim
