// The Teensy 4.0 and 4.1 as a module sees them: how many pins, and which have an analog input.
#pragma once

#include <stdint.h>

namespace stepdance {

/// Marks a pin the board does not have.
constexpr uint8_t kNoPin = 255;

/// Pin facts of one Teensy model, from PJRC's pinout cards.
struct TeensyPinout {
  const char* name;
  uint8_t highest_pin;  ///< digital pins are 0..highest_pin (bottom pads included)
  uint8_t analog_pin_count;
  uint8_t analog_pins[18];  ///< the pins of A0, A1, … in order
};

/// Teensy 4.0: pins 0–39 (24–39 on the bottom pads); A0–A13 on pins 14–27.
inline constexpr TeensyPinout kTeensy40 = {
    "Teensy 4.0", 39, 14, {14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27}};

/// Teensy 4.1: pins 0–54 (0–41 on the edges, the rest on the SD socket and bottom pads); A0–A13
/// on pins 14–27, A14–A17 on 38–41.
inline constexpr TeensyPinout kTeensy41 = {
    "Teensy 4.1", 54, 18, {14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 38, 39, 40, 41}};

/// Whether `pin` has an analog input on `teensy`. Context: any.
constexpr bool has_analog_input(const TeensyPinout& teensy, uint8_t pin) {
  for (uint8_t i = 0; i < teensy.analog_pin_count; ++i) {
    if (teensy.analog_pins[i] == pin) return true;
  }
  return false;
}

/// Whether `pin` is a pin of `teensy` (kNoPin is not). Context: any.
constexpr bool has_pin(const TeensyPinout& teensy, uint8_t pin) { return pin <= teensy.highest_pin; }

}  // namespace stepdance
