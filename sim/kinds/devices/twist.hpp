// Device kind "twist": the SparkFun Qwiic Twist knob (a detented knob and a button) on a QWIIC bus.
#pragma once

#include "kinds/device_kind.hpp"

namespace stepdance::sim {

/// A Twist has no settings of its own (its I2C address is the device's i2c_address).
struct TwistConfig {};

const DeviceKind& twist_kind();

}  // namespace stepdance::sim
