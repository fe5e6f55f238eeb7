// Our Teensy backend's pin table (src/stepdance/platform/teensy/pins.hpp), evaluated at compile
// time for one Teensy, so that a host test can compare the simulator's pinout against it. The
// including test defines the board (ARDUINO_TEENSY40 or not) first; only constant expressions
// of the backend are used, so nothing of its register access code is compiled in.
#pragma once

#include <array>
#include <cstdint>

#define __IMXRT1062__ 1  // the backend's headers exist only for the RT1062
#include "stepdance/platform/teensy/pins.hpp"
#undef __IMXRT1062__

namespace stepdance::sim::image::rt1062::testing {

/// One backend pin: SW_MUX_CTL offset, standard GPIO port (1..4) and bit.
struct BackendPin {
  uint16_t mux;
  uint8_t port;
  uint8_t bit;
};

constexpr uint8_t kBackendMaxPin = platform::teensy::kMaxPin;

constexpr std::array<BackendPin, kBackendMaxPin + 1> backend_pins() {
  std::array<BackendPin, kBackendMaxPin + 1> pins{};
  for (uint8_t pin = 0; pin <= kBackendMaxPin; ++pin) {
    const platform::teensy::PinInfo info = platform::teensy::pin_pad(pin);
    pins[pin] = {info.mux, static_cast<uint8_t>(info.port + 1u), info.bit};  // fast GPIO6..9 = GPIO1..4
  }
  return pins;
}

}  // namespace stepdance::sim::image::rt1062::testing
