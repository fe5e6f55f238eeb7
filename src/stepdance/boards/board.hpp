// Board definitions: which pins and ports a Stepdance module has, as constexpr tables.
#pragma once

#include <stdint.h>

namespace stepdance {

/// Marks a pin the board does not have.
constexpr uint8_t kNoPin = 255;

/// Pins of one motion-stream output port and, on a Driver Module, of its driver socket.
struct OutputPortPins {
  uint8_t step = kNoPin;
  uint8_t dir = kNoPin;
  uint8_t enable = kNoPin;  ///< driver ENABLE, active low
  uint8_t vref = kNoPin;    ///< analog read-back of the driver's current-setting voltage
  uint8_t limit = kNoPin;   ///< limit-switch input (5 V header, high = switch active)
};

/// Pins of one motion-stream input port.
struct InputPortPins {
  uint8_t step = kNoPin;
  uint8_t dir = kNoPin;
};

/// Everything the core needs to know about a module's wiring.
struct BoardDefinition {
  const char* name;
  uint8_t output_port_count;
  OutputPortPins output_ports[4];
  uint8_t input_port_count;
  InputPortPins input_ports[4];
  uint8_t encoder_pins[2][2];  ///< ENC1 A/B, ENC2 A/B
  uint8_t io_a[4];             ///< A1..A4 (analog or digital)
  uint8_t io_d[2];             ///< D1..D2 (digital)
  bool has_drivers;            ///< driver sockets with ENABLE and VREF
  uint8_t qwiic[2][2];         ///< QWIIC0, QWIIC1: SDA/SCL (Teensy Wire 18/19, Wire1 17/16)
};

/// Stepdance Driver Module v1.0 (Teensy 4.1): four driver sockets, four input ports.
constexpr BoardDefinition kDriverModuleV1 = {
    "Driver Module v1.0",
    4,
    {{23, 22, 14, 15, 29}, {21, 20, 13, 41, 30}, {37, 36, 39, 40, 31}, {35, 34, 33, 38, 32}},
    4,
    {{4, 6}, {5, 7}, {8, 10}, {9, 11}},
    {{0, 1}, {2, 3}},
    {24, 26, 27, 25},
    {28, 12},
    true,
    {{18, 19}, {17, 16}},  // QWIIC1 shares 17/16 with Serial4 (TX4/RX4)
};

/// Stepdance Basic Module v1.0 (Teensy 4.0 or 4.1): one input and one output port, no drivers.
constexpr BoardDefinition kBasicModuleV1 = {
    "Basic Module v1.0",
    1,
    {{23, 22, kNoPin, kNoPin, kNoPin}, {}, {}, {}},
    1,
    {{4, 6}, {}, {}, {}},
    {{0, 1}, {2, 3}},
    {14, 15, 20, 21},
    {13, 12},
    false,
    {{18, 19}, {17, 16}},
};

/// The board the core is running on. Defaults to the Driver Module. Context: any.
const BoardDefinition& active_board();
/// Chooses the board; called by the umbrella header from the sketch's module macro, before
/// setup(). Context: loop, before any begin().
void select_board(const BoardDefinition& board);

}  // namespace stepdance
