// The Teensy core's pin-mode numbers (Arduino's INPUT, INPUT_PULLUP, INPUT_PULLDOWN macros), for
// code that takes a sketch's mode argument without including Arduino.h: Button::begin(pin, mode),
// and the simulator's Arduino layer, which checks its own macros against them.
#pragma once

#include <stdint.h>

namespace stepdance::arduino_pin_mode {

constexpr uint8_t kInput = 0;
constexpr uint8_t kInputPullup = 2;
constexpr uint8_t kInputPulldown = 3;

}  // namespace stepdance::arduino_pin_mode
