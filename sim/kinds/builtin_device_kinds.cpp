// The built-in device kinds, one line each, in the order messages list them.
#include "kinds/device_registry.hpp"
#include "kinds/devices/button.hpp"
#include "kinds/devices/encoder.hpp"
#include "kinds/devices/five_bar_arm.hpp"
#include "kinds/devices/limit_switch.hpp"
#include "kinds/devices/oled.hpp"
#include "kinds/devices/pendulum.hpp"
#include "kinds/devices/potentiometer.hpp"
#include "kinds/devices/twist.hpp"

namespace stepdance::sim {

std::vector<const DeviceKind*> builtin_device_kinds() {
  return {
      &encoder_kind(),  &potentiometer_kind(), &button_kind(), &limit_switch_kind(),
      &pendulum_kind(), &five_bar_arm_kind(),  &oled_kind(),   &twist_kind(),
  };
}

}  // namespace stepdance::sim
