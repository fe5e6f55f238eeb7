// Which Teensy 4.x carries the emulated i.MX RT1062: it decides which pads reach a Teensy pin.
#pragma once

#include <cstdint>

namespace stepdance::sim::image {

/// The Teensy an image board emulates (PJRC's pinout cards: the 4.0 has pins 0..39, the 4.1 0..54).
enum class TeensyModel : uint8_t { kTeensy40, kTeensy41 };

}  // namespace stepdance::sim::image
