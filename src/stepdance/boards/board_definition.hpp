// The shape of a board table: which pins, ports, connectors and buses a Stepdance module has.
#pragma once

#include <stdint.h>

#include "stepdance/boards/teensy_pinout.hpp"

namespace stepdance {

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

/// Most ports of either kind a board can have (A..D).
constexpr uint8_t kMaxBoardPorts = 4;

/// Everything the core, the Teensy backend, the simulator and the scenario reader know about a
/// module's wiring. A connector the module lacks has kNoPin in its place. One constant of this
/// type per board (boards/<board>.hpp), listed in boards/board_registry.hpp.
struct BoardDefinition {
  const char* name;            ///< "Driver Module v1.0": what messages and active_board() show
  const char* scenario_name;   ///< "driver": the scenario file's `module` value
  const char* sketch_macro;    ///< "module_driver": the #define a sketch selects it with
  const TeensyPinout* teensy;  ///< the Teensy it is built around; the simulator models this one
  /// A second Teensy it also takes, or `teensy` again when it takes one. Never null: a constant
  /// expression cannot compare an inline variable's address with null under GCC's sanitizers,
  /// and the registry's static_assert checks both in every build.
  const TeensyPinout* other_teensy;
  uint8_t output_port_count;
  OutputPortPins output_ports[kMaxBoardPorts];
  uint8_t input_port_count;
  InputPortPins input_ports[kMaxBoardPorts];
  uint8_t encoder_pins[2][2];  ///< ENC1 A/B, ENC2 A/B
  uint8_t io_a[4];             ///< A1..A4 (analog or digital): ADC channels of the board
  uint8_t io_d[2];             ///< D1..D2 (digital)
  bool has_drivers;            ///< driver sockets (with ENABLE and VREF) on the output ports
  uint8_t qwiic[2][2];         ///< QWIIC0, QWIIC1: I2C bus 0/1 SDA/SCL
};

/// Whether the board can sit on `teensy`. Context: any (constant expression).
constexpr bool board_takes(const BoardDefinition& board, const TeensyPinout& teensy) {
  return board.teensy == &teensy || board.other_teensy == &teensy;
}

/// Whether two C strings are equal (constant expression; no <string.h> in the core).
constexpr bool same_text(const char* a, const char* b) {
  while (*a != '\0' && *a == *b) {
    ++a;
    ++b;
  }
  return *a == *b;
}

}  // namespace stepdance
