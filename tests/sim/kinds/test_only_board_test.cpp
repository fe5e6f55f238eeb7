// The map of docs/architecture.md ("A new board"), proved: a board defined only in the test tree
// (TestModuleSketch/test_module.hpp) and registered with a ScopedKind<BoardRegistry> is read from
// a scenario file, checked against its own table, and runs a real sketch whose HAL and whose
// simulated board both use that table — with no other file edited.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "kinds/board_registry.hpp"
#include "sim/assembly/simulation_fixture.hpp"
#include "sim/kinds/TestModuleSketch/test_module.hpp"

namespace stepdance::sim::test {
namespace {

using stepdance::test::kTestModule;

const std::string kFile = "/tmp/test_only_board/scenario.toml";

std::string board_text(const std::string& module, const std::string& extra = "") {
  return "duration_s = 2\n"
         "[[board]]\nname = \"b\"\nsketch = \"" +
         source_path("tests/sim/kinds/TestModuleSketch/TestModuleSketch.ino") + "\"\nmodule = \"" + module + "\"\n" +
         extra;
}

std::string device_text(const std::string& name, const std::string& type, const std::string& connector) {
  return "[[device]]\nname = \"" + name + "\"\ntype = \"" + type + "\"\nboard = \"b\"\nconnector = \"" + connector +
         "\"\n";
}

std::vector<std::string> errors_of(const std::string& text) {
  std::vector<std::string> errors;
  for (const scenario::Diagnostic& error : scenario::parse_scenario(text, kFile).errors)
    errors.push_back(error.to_string());
  return errors;
}

class TestOnlyBoard : public ::testing::Test {
 protected:
  ScopedKind<BoardRegistry> board_{kTestModule};
};

TEST(TestOnlyBoardRegistry, IsUnknownUntilRegisteredAndGoneAfter) {
  EXPECT_EQ(find_board("test"), nullptr);
  EXPECT_EQ(board_names(), "\"driver\" or \"basic\"");
  {
    ScopedKind<BoardRegistry> board(kTestModule);
    EXPECT_EQ(find_board("test"), &kTestModule);
    EXPECT_EQ(find_board_named("Test Module v0"), &kTestModule);
    EXPECT_EQ(board_names(), "\"driver\", \"basic\" or \"test\"");
  }
  EXPECT_EQ(find_board("test"), nullptr);
  EXPECT_EQ(find_board_named("Test Module v0"), nullptr);
}

TEST(TestOnlyBoardRegistry, AnUnregisteredModuleIsRefused) {
  EXPECT_EQ(errors_of(board_text("test")),
            (std::vector<std::string>{kFile + ":5: 'module' must be \"driver\" or \"basic\", got \"test\""}));
}

TEST_F(TestOnlyBoard, TheReaderTakesItsName) {
  const scenario::Scenario read = parse(board_text("test"), kFile);
  ASSERT_EQ(read.boards.size(), 1u);
  EXPECT_EQ(read.boards[0].module, &kTestModule);
  EXPECT_EQ(
      errors_of(board_text("lathe")),
      (std::vector<std::string>{kFile + ":5: 'module' must be \"driver\", \"basic\" or \"test\", got \"lathe\""}));
}

TEST_F(TestOnlyBoard, ItsConnectorsAreThoseOfItsTable) {
  // The table has ENC1, A1, A2, D1 and QWIIC0; not ENC2, A3, A4, D2 or QWIIC1.
  const std::string present = device_text("k", "encoder", "ENC1") + device_text("p", "potentiometer", "A2") +
                              device_text("d", "button", "D1") + device_text("o", "oled", "QWIIC0");
  EXPECT_EQ(errors_of(board_text("test") + present), std::vector<std::string>{});
  // Lines 6, 11, 16 and 21 open the four [[device]] tables; each `connector` is 4 lines further.
  const std::string absent = device_text("k2", "encoder", "ENC2") + device_text("p3", "potentiometer", "A3") +
                             device_text("d2", "button", "D2") + device_text("o1", "oled", "QWIIC1");
  EXPECT_EQ(errors_of(board_text("test") + absent),
            (std::vector<std::string>{kFile + ":10: board 'b' (test module) has no connector ENC2",
                                      kFile + ":15: board 'b' (test module) has no connector A3",
                                      kFile + ":20: board 'b' (test module) has no connector D2",
                                      kFile + ":25: board 'b' (test module) has no connector QWIIC1"}));
}

TEST_F(TestOnlyBoard, ItsPortsAndSocketsAreThoseOfItsTable) {
  // Two output ports (A, B) with driver sockets, one input port (A).
  EXPECT_EQ(errors_of(board_text("test", "sockets = { C = { device = \"stepper\" } }\n")),
            (std::vector<std::string>{kFile + ":6: unknown socket 'C' (sockets are A and B)"}));
  const std::string cables = "[[cable]]\nfrom = \"b:C\"\nto = \"b:A\"\n[[cable]]\nfrom = \"b:B\"\nto = \"b:B\"\n";
  EXPECT_EQ(errors_of(board_text("test") + cables),
            (std::vector<std::string>{kFile + ":7: board 'b' (test module) has no output port C",
                                      kFile + ":11: board 'b' (test module) has no input port B"}));
}

TEST_F(TestOnlyBoard, RunsItsSketchOnItsOwnPins) {
  // Knob 1 turns +1200 counts: one step per count on socket B, whose ENABLE the sketch drives
  // through its own table (pin 32) and the simulated socket follows through the registry's.
  // The pot at 0.25 reads round(0.25 × 1023) = 256 on A1 (pin 26, an analog pin of the table).
  const std::string text = board_text("test", "sockets = { B = { device = \"stepper\" } }\n") +
                           device_text("knob", "encoder", "ENC1") + device_text("pot", "potentiometer", "A1") +
                           "position = 0.25\n"
                           "[[at]]\ntime_s = 0.2\nturn = \"knob\"\ncounts = 1200\nover_s = 1\n"
                           "[[expect]]\nmotor = \"b:B\"\nsteps = 1200\n";
  auto simulation = create(parse(text, kFile), "test_only_board", false);
  ASSERT_NE(simulation, nullptr);
  const SimulationReport report = simulation->finish();
  ASSERT_EQ(report.expectations.size(), 1u);
  EXPECT_TRUE(report.expectations[0].met) << report.expectations[0].message;
  const SimBoard& board = *simulation->board("b");
  EXPECT_STREQ(board.definition().name, "Test Module v0");
  EXPECT_NE(board.console().text().find("A1 256\r\n"), std::string::npos) << board.console().text();
  EXPECT_TRUE(board.pin_level(28));   // D1 of the table, driven high
  EXPECT_FALSE(board.pin_level(45));  // a Teensy 4.1 pin: the board's Teensy 4.0 has none
}

TEST_F(TestOnlyBoard, AScenarioThatNamesAnotherModuleIsRefused) {
  SimulationOptions options;
  plug_test_hooks(options);
  options.output_directory = test_output_dir("test_only_board_mismatch");
  SimulationError error;
  EXPECT_EQ(Simulation::create(parse(board_text("driver"), kFile), options, error), nullptr);
  EXPECT_EQ(error.message, kFile +
                               ":2: board 'b' is a Driver Module v1.0 in the scenario, but its sketch selects the "
                               "Test Module v0 (#define STEPDANCE_BOARD stepdance::test::kTestModule)");
}

TEST(TestOnlyBoardRegistry, ASketchOnAnUnregisteredBoardIsRefused) {
  SimulationOptions options;
  plug_test_hooks(options);
  options.output_directory = test_output_dir("test_only_board_unknown");
  SimulationError error;
  EXPECT_EQ(Simulation::create(parse(board_text("driver"), kFile), options, error), nullptr);
  EXPECT_NE(error.message.find("b: the sketch selects the board \"Test Module v0\", which the simulator does not know"),
            std::string::npos)
      << error.message;
}

}  // namespace
}  // namespace stepdance::sim::test
