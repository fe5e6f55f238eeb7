// Device kind "oled": the SparkFun QWIIC OLED (SSD1306, 128×32) on QWIIC0 or QWIIC1.
#pragma once

#include <vector>

#include "kinds/device_kind.hpp"

namespace stepdance::sim {

/// An OLED's settings (its I2C address is the device's i2c_address): the times (s) at which a
/// picture of its screen is written, besides the one at the end.
struct OledConfig {
  std::vector<double> snapshots_s;
};

const DeviceKind& oled_kind();

}  // namespace stepdance::sim
