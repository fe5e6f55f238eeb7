// The board tables against the facts written down elsewhere: the original library's port and
// board-macro tables (shared/reference/original-library.md §4.3–4.5 and §6), the module
// documentation (QWIIC0 = I2C0, QWIIC1 = I2C1 with TX4/RX4) and PJRC's Teensy 4.0/4.1 pinout cards.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "stepdance/boards/board.hpp"

namespace stepdance {
namespace {

struct PortFacts {
  uint8_t step, dir, enable, vref, limit;
};

// Original library §4.3: output ports A–D (STEP, DIR, ENABLE, VREF, LIMIT).
constexpr PortFacts kDriverOutputs[4] = {
    {23, 22, 14, 15, 29}, {21, 20, 13, 41, 30}, {37, 36, 39, 40, 31}, {35, 34, 33, 38, 32}};
// §4.4: input ports A–D (STEP, DIR).
constexpr uint8_t kInputs[4][2] = {{4, 6}, {5, 7}, {8, 10}, {9, 11}};

void expect_output(const OutputPortPins& pins, const PortFacts& facts, int port) {
  EXPECT_EQ(pins.step, facts.step) << "port " << port;
  EXPECT_EQ(pins.dir, facts.dir) << "port " << port;
  EXPECT_EQ(pins.enable, facts.enable) << "port " << port;
  EXPECT_EQ(pins.vref, facts.vref) << "port " << port;
  EXPECT_EQ(pins.limit, facts.limit) << "port " << port;
}

TEST(DriverModuleV1, PortsAreTheOriginalsFour) {
  const BoardDefinition& board = kDriverModuleV1;
  ASSERT_EQ(board.output_port_count, 4);
  ASSERT_EQ(board.input_port_count, 4);
  for (int port = 0; port < 4; ++port) {
    expect_output(board.output_ports[port], kDriverOutputs[port], port);
    EXPECT_EQ(board.input_ports[port].step, kInputs[port][0]);
    EXPECT_EQ(board.input_ports[port].dir, kInputs[port][1]);
  }
  EXPECT_TRUE(board.has_drivers);
}

TEST(DriverModuleV1, ConnectorsAreTheModuleDriverMacros) {
  // §6, module_driver: IO_A1..A4 = 24, 26, 27, 25; IO_D1/D2 = 28, 12. §4.5: ENC1 0/1, ENC2 2/3.
  const BoardDefinition& board = kDriverModuleV1;
  EXPECT_EQ(board.io_a[0], 24);
  EXPECT_EQ(board.io_a[1], 26);
  EXPECT_EQ(board.io_a[2], 27);
  EXPECT_EQ(board.io_a[3], 25);
  EXPECT_EQ(board.io_d[0], 28);
  EXPECT_EQ(board.io_d[1], 12);
  EXPECT_EQ(board.encoder_pins[0][0], 0);
  EXPECT_EQ(board.encoder_pins[0][1], 1);
  EXPECT_EQ(board.encoder_pins[1][0], 2);
  EXPECT_EQ(board.encoder_pins[1][1], 3);
}

TEST(BasicModuleV1, OnePortEachAndNoDriverPins) {
  // §6, module_basic: one input (4/6) and one output (23/22); VREF, ENABLE and LIMIT are 255.
  const BoardDefinition& board = kBasicModuleV1;
  ASSERT_EQ(board.output_port_count, 1);
  ASSERT_EQ(board.input_port_count, 1);
  expect_output(board.output_ports[0], {23, 22, 255, 255, 255}, 0);
  EXPECT_EQ(board.input_ports[0].step, 4);
  EXPECT_EQ(board.input_ports[0].dir, 6);
  EXPECT_FALSE(board.has_drivers);
  for (int port = 1; port < 4; ++port) {
    expect_output(board.output_ports[port], {255, 255, 255, 255, 255}, port);
    EXPECT_EQ(board.input_ports[port].step, 255);
  }
}

TEST(BasicModuleV1, ConnectorsAreTheModuleBasicMacros) {
  // §6, module_basic: IO_A1..A4 = 14, 15, 20, 21; IO_D1/D2 = 13, 12; encoders as the Driver's.
  const BoardDefinition& board = kBasicModuleV1;
  EXPECT_EQ(board.io_a[0], 14);
  EXPECT_EQ(board.io_a[1], 15);
  EXPECT_EQ(board.io_a[2], 20);
  EXPECT_EQ(board.io_a[3], 21);
  EXPECT_EQ(board.io_d[0], 13);
  EXPECT_EQ(board.io_d[1], 12);
  EXPECT_EQ(board.encoder_pins[0][0], 0);
  EXPECT_EQ(board.encoder_pins[1][1], 3);
}

TEST(BoardTables, QwiicIsWireAndWire1) {
  // QWIIC0 = I2C0 (Teensy SDA0 18, SCL0 19); QWIIC1 = I2C1 (SDA1 17, SCL1 16, also TX4/RX4).
  for (const BoardDefinition* board : kBoards) {
    EXPECT_EQ(board->qwiic[0][0], 18) << board->name;
    EXPECT_EQ(board->qwiic[0][1], 19) << board->name;
    EXPECT_EQ(board->qwiic[1][0], 17) << board->name;
    EXPECT_EQ(board->qwiic[1][1], 16) << board->name;
  }
}

TEST(BoardTables, TeensiesAreThoseTheModulesTake) {
  // The Driver Module carries a Teensy 4.1; the Basic Module a 4.0 or a 4.1.
  EXPECT_TRUE(board_takes(kDriverModuleV1, kTeensy41));
  EXPECT_FALSE(board_takes(kDriverModuleV1, kTeensy40));
  EXPECT_TRUE(board_takes(kBasicModuleV1, kTeensy41));
  EXPECT_TRUE(board_takes(kBasicModuleV1, kTeensy40));
}

TEST(BoardRegistry, ListsBothModulesUnderTheirScenarioNamesAndMacros) {
  ASSERT_EQ(kBoardCount, 2u);
  EXPECT_EQ(kBoards[0], &kDriverModuleV1);
  EXPECT_EQ(kBoards[1], &kBasicModuleV1);
  EXPECT_STREQ(kDriverModuleV1.scenario_name, "driver");
  EXPECT_STREQ(kBasicModuleV1.scenario_name, "basic");
  EXPECT_STREQ(kDriverModuleV1.sketch_macro, "module_driver");
  EXPECT_STREQ(kBasicModuleV1.sketch_macro, "module_basic");
  EXPECT_STREQ(kDriverModuleV1.name, "Driver Module v1.0");
  EXPECT_STREQ(kBasicModuleV1.name, "Basic Module v1.0");
}

// PJRC's pinout cards: Teensy 4.0 has 40 digital pins (0–39) and A0–A13 on pins 14–27; the
// Teensy 4.1 has 55 (0–54) and adds A14–A17 on pins 38–41.
TEST(TeensyPinouts, DigitalAndAnalogPinsAreThePinoutCards) {
  EXPECT_EQ(kTeensy40.highest_pin + 1, 40);
  EXPECT_EQ(kTeensy41.highest_pin + 1, 55);
  std::set<int> analog40;
  std::set<int> analog41;
  for (int pin = 0; pin < 256; ++pin) {
    if (has_analog_input(kTeensy40, static_cast<uint8_t>(pin))) analog40.insert(pin);
    if (has_analog_input(kTeensy41, static_cast<uint8_t>(pin))) analog41.insert(pin);
  }
  std::set<int> expected40;
  for (int a = 0; a <= 13; ++a) expected40.insert(14 + a);
  std::set<int> expected41 = expected40;
  for (int a = 14; a <= 17; ++a) expected41.insert(38 + (a - 14));
  EXPECT_EQ(analog40, expected40);
  EXPECT_EQ(analog41, expected41);
  EXPECT_TRUE(has_pin(kTeensy40, 39));
  EXPECT_FALSE(has_pin(kTeensy40, 40));
  EXPECT_TRUE(has_pin(kTeensy41, 54));
  EXPECT_FALSE(has_pin(kTeensy41, 55));
  EXPECT_FALSE(has_pin(kTeensy41, kNoPin));
}

TEST(BoardChecks, AcceptTheBuiltInBoards) {
  for (const BoardDefinition* board : kBoards) EXPECT_TRUE(board_is_valid(*board)) << board->name;
}

TEST(BoardChecks, RefuseAVrefWithoutAnalogInput) {
  BoardDefinition board = kDriverModuleV1;
  board.output_ports[1].vref = 30;  // pin 30 is digital only
  EXPECT_FALSE(board_is_valid(board));
}

TEST(BoardChecks, RefuseAPinTheSecondTeensyLacks) {
  BoardDefinition board = kBasicModuleV1;
  board.io_a[3] = 41;  // A17 of a Teensy 4.1, no pin at all on a 4.0
  EXPECT_FALSE(board_is_valid(board));
  board.other_teensy = board.teensy;  // a module for the 4.1 only may use it
  EXPECT_TRUE(board_is_valid(board));
}

TEST(BoardChecks, RefuseAPortWithoutItsPinsOrPinsBeyondTheCount) {
  BoardDefinition board = kBasicModuleV1;
  board.output_port_count = 2;  // port B has no STEP/DIR
  EXPECT_FALSE(board_is_valid(board));
  board = kBasicModuleV1;
  board.input_ports[2] = {8, 10};  // pins for a port the count leaves out
  EXPECT_FALSE(board_is_valid(board));
}

TEST(BoardChecks, RefuseDriverSocketsWithoutEnable) {
  BoardDefinition board = kDriverModuleV1;
  board.output_ports[3].enable = kNoPin;
  EXPECT_FALSE(board_is_valid(board));
}

}  // namespace
}  // namespace stepdance
