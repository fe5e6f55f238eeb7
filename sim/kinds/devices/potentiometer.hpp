// Device kind "potentiometer": a pot on A1..A4, moved by the timeline.
#pragma once

#include "kinds/device_kind.hpp"

namespace stepdance::sim {

/// A potentiometer's settings: the wiper's position at time 0, 0..1.
struct PotentiometerConfig {
  double position = 0.5;
};

const DeviceKind& potentiometer_kind();

}  // namespace stepdance::sim
