// Device kind "button": a push button on D1, D2 or A1..A4, pressed by the timeline.
#pragma once

#include "kinds/device_kind.hpp"

namespace stepdance::sim {

/// A button's settings: bounce after each press and release (ms) and the level while pressed.
struct ButtonConfig {
  double bounce_ms = 2;
  bool pressed_level_high = true;
};

const DeviceKind& button_kind();

}  // namespace stepdance::sim
