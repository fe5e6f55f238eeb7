// Teensy 4.0 and 4.1 pin numbers → RT1062 pads (and so GPIO port bits). Public pinout facts;
// fact source: PJRC's Teensyduino core, teensy4/core_pins.h (tag 1.59), CORE_PINn_CONFIG (the
// pad) and CORE_PINn_PORTREG/_BIT (the fast GPIO port bit), for both boards.
#pragma once

#include <cstdint>

#include "image/rt1062/teensy_model.hpp"

namespace stepdance::sim::image::rt1062 {

/// The highest pin number of a model (4.0: 39, 4.1: 54).
uint8_t highest_pin(TeensyModel model);
/// The pad (pads.hpp index) of Teensy pin `pin`, or -1 if the model has no such pin.
int teensy_pin_pad(TeensyModel model, uint8_t pin);
/// The Teensy pin on pad `pad`, or -1 if no pin of the model reaches it.
int pad_teensy_pin(TeensyModel model, int pad);

}  // namespace stepdance::sim::image::rt1062
