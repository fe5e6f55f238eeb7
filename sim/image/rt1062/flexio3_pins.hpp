// Where FlexIO3's pins come out: FlexIO3 pin → Teensy pin → output port STEP/DIR line.
#pragma once

#include <cstdint>

#include "image/rt1062/teensy_model.hpp"

namespace stepdance::sim::image {

/// Marks "no such pin or port".
constexpr uint8_t kNoFlexioRoute = 0xFF;

/// The Teensy pin whose pad carries FlexIO3 pin `flexio_pin` (0..31) in ALT9, or kNoFlexioRoute.
/// Pads: GPIO_AD_B1_nn → FLEXIO3_FLEXIOnn, GPIO_B1_nn → FLEXIO3_FLEXIO(16+nn) (RM §11.7,
/// SW_MUX_CTL_PAD_GPIO_AD_B1_xx / _B1_xx ALT9); pad of each Teensy pin from PJRC's schematics.
/// Context: any.
uint8_t flexio3_teensy_pin(TeensyModel model, uint8_t flexio_pin);

/// One output-port line: the port (0..3 = A..D) and whether it is the DIR line (else STEP).
struct PortLine {
  uint8_t port = kNoFlexioRoute;
  bool is_dir = false;
};

/// The output-port line on Teensy pin `teensy_pin`, from the board table the Teensy backend
/// wires its ports with (stepdance/boards: kDriverModuleV1.output_ports; every board's port n
/// uses the same pins, as output_ports.cpp asserts). Port kNoFlexioRoute if none. Context: any.
PortLine output_port_line(uint8_t teensy_pin);

}  // namespace stepdance::sim::image
