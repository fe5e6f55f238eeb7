// Compile-time checks of a board table against its Teensy: every pin exists, analog pins are analog.
#pragma once

#include "stepdance/boards/board_definition.hpp"

namespace stepdance {

/// Whether `pin` is absent or a pin of `teensy`.
constexpr bool pin_fits(const TeensyPinout& teensy, uint8_t pin) { return pin == kNoPin || has_pin(teensy, pin); }

/// Whether `pin` is absent or has an analog input on `teensy`.
constexpr bool analog_pin_fits(const TeensyPinout& teensy, uint8_t pin) {
  return pin == kNoPin || has_analog_input(teensy, pin);
}

/// Whether every port the board lists has both its STEP and DIR pins, on `teensy`, and the ports
/// beyond its count are empty.
constexpr bool ports_fit(const BoardDefinition& board, const TeensyPinout& teensy) {
  for (uint8_t port = 0; port < kMaxBoardPorts; ++port) {
    const OutputPortPins& out = board.output_ports[port];
    const InputPortPins& in = board.input_ports[port];
    const bool out_used = port < board.output_port_count;
    const bool in_used = port < board.input_port_count;
    if (out_used != (out.step != kNoPin) || out_used != (out.dir != kNoPin)) return false;
    if (in_used != (in.step != kNoPin) || in_used != (in.dir != kNoPin)) return false;
    if (!pin_fits(teensy, out.step) || !pin_fits(teensy, out.dir) || !pin_fits(teensy, out.enable) ||
        !analog_pin_fits(teensy, out.vref) || !pin_fits(teensy, out.limit)) {
      return false;
    }
    if (!pin_fits(teensy, in.step) || !pin_fits(teensy, in.dir)) return false;
    if (board.has_drivers && out_used && out.enable == kNoPin) return false;
  }
  return true;
}

/// Whether the encoders, A1–A4 (analog), D1–D2 and QWIIC pins are absent or on `teensy`.
constexpr bool connectors_fit(const BoardDefinition& board, const TeensyPinout& teensy) {
  for (const auto& encoder : board.encoder_pins) {
    if (!pin_fits(teensy, encoder[0]) || !pin_fits(teensy, encoder[1])) return false;
  }
  for (uint8_t pin : board.io_a) {
    if (!analog_pin_fits(teensy, pin)) return false;
  }
  for (uint8_t pin : board.io_d) {
    if (!pin_fits(teensy, pin)) return false;
  }
  for (const auto& bus : board.qwiic) {
    if (!pin_fits(teensy, bus[0]) || !pin_fits(teensy, bus[1])) return false;
  }
  return true;
}

/// Whether the table is whole and fits every Teensy the board takes. Context: any (constant
/// expression; boards/board_registry.hpp asserts it for every built-in board).
constexpr bool board_is_valid(const BoardDefinition& board) {
  if (board.output_port_count > kMaxBoardPorts || board.input_port_count > kMaxBoardPorts) return false;
  if (!ports_fit(board, *board.teensy) || !connectors_fit(board, *board.teensy)) return false;
  return ports_fit(board, *board.other_teensy) && connectors_fit(board, *board.other_teensy);
}

}  // namespace stepdance
