// FlexIO3 pads of the Teensy 4.0/4.1 and the board table's output-port pins.
#include "image/rt1062/flexio3_pins.hpp"

#include "stepdance/boards/driver_module_v1.hpp"

namespace stepdance::sim::image {
namespace {

/// FlexIO3 pin → Teensy pin on both Teensys (pins 0..33 are the same pads on the 4.0 and 4.1):
/// 19 = AD_B1_00, 18 = AD_B1_01, 14 = AD_B1_02, 15 = AD_B1_03, 17 = AD_B1_06, 16 = AD_B1_07,
/// 22 = AD_B1_08, 23 = AD_B1_09, 20 = AD_B1_10, 21 = AD_B1_11, 26 = AD_B1_14, 27 = AD_B1_15,
/// 8 = B1_00, 7 = B1_01.
constexpr uint8_t kN = kNoFlexioRoute;
constexpr uint8_t kCommon[32] = {19, 18, 14, 15, kN, kN, 17, 16, 22, 23, 20, 21, kN, kN, 26, 27,   // 0-15
                                 8,  7,  kN, kN, kN, kN, kN, kN, kN, kN, kN, kN, kN, kN, kN, kN};  // 16-31
/// Teensy 4.1 only: 40 = AD_B1_04, 41 = AD_B1_05, 38 = AD_B1_12, 39 = AD_B1_13, 36 = B1_02,
/// 37 = B1_03, 35 = B1_12, 34 = B1_13 (the 4.0's pins 34..39 are SD pads without FlexIO3).
constexpr uint8_t kTeensy41Only[32] = {kN, kN, kN, kN, 40, 41, kN, kN, kN, kN, kN, kN, 38, 39, kN, kN,   // 0-15
                                       kN, kN, 36, 37, kN, kN, kN, kN, kN, kN, kN, kN, 35, 34, kN, kN};  // 16-31

}  // namespace

uint8_t flexio3_teensy_pin(TeensyModel model, uint8_t flexio_pin) {
  if (flexio_pin >= 32) return kNoFlexioRoute;
  if (kCommon[flexio_pin] != kNoFlexioRoute) return kCommon[flexio_pin];
  return model == TeensyModel::kTeensy41 ? kTeensy41Only[flexio_pin] : kNoFlexioRoute;
}

PortLine output_port_line(uint8_t teensy_pin) {
  const BoardDefinition& board = kDriverModuleV1;
  for (uint8_t port = 0; port < board.output_port_count; ++port) {
    if (board.output_ports[port].step == teensy_pin) return {port, false};
    if (board.output_ports[port].dir == teensy_pin) return {port, true};
  }
  return {};
}

}  // namespace stepdance::sim::image
