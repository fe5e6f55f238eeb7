// The terminals a board is wired at, one type each, and what each takes: SimBoard::wire(terminal,
// …) is the one way the rest of the simulation connects to a board.
#pragma once

#include <cstdint>
#include <functional>

#include "common/sim_time.hpp"

namespace stepdance::sim {

class I2cDevice;
class WireListener;

/// Where something plugs into a board. What it takes follows the direction of the signal: an
/// input terminal takes a source the board reads when the sketch reads it (a function of
/// simulated time: nothing runs between reads); an output terminal takes a listener the board
/// calls when the sketch changes it; an I2C address takes the device that answers transfers.
namespace terminal {

/// Quadrature decoder `index` (0 = ENC1, 1 = ENC2): takes a count source.
struct Encoder {
  uint8_t index;
};
/// The ADC of Teensy pin `pin`: takes a level source, 0..1023.
struct Analog {
  uint8_t pin;
};
/// Teensy pin `pin` as the sketch's input: takes a level source (a button, a limit switch).
struct InputPin {
  uint8_t pin;
};
/// Teensy pin `pin` as the sketch's output: takes a change listener (a driver's ENABLE).
struct OutputPin {
  uint8_t pin;
};
/// Output port `port`'s STEP/DIR wire (0 = A): takes a WireListener (not owned).
struct OutputPort {
  uint8_t port;
};
/// 7-bit `address` on QWIIC bus `bus` (0 or 1): takes an I2cDevice (not owned).
struct I2c {
  uint8_t bus;
  uint8_t address;
};

}  // namespace terminal

/// A value as a function of simulated time (ns), read when the sketch reads its terminal.
template <typename T>
using Source = std::function<T(SimTime)>;
/// Told when an output pin changes: (time, level, whether the pin is driven as an output).
using PinListener = std::function<void(SimTime, bool level, bool driven)>;

}  // namespace stepdance::sim
