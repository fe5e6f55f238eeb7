// The map of docs/architecture.md ("Where things go") for checks, proved: an expectation kind
// defined only in this folder (test_turns.hpp) is read from a scenario file, its keys checked like
// the built-in ones', and checked at the end of a run under a real sketch — with no other file
// edited.
#include <gtest/gtest.h>

#include <string>

#include "sim/assembly/simulation_fixture.hpp"
#include "sim/kinds/test_crank.hpp"
#include "sim/kinds/test_turns.hpp"

namespace stepdance::sim::test {
namespace {

const std::string kFile = "/tmp/test_expectation_kind/scenario.toml";

/// StepASketch (knob 1 on ENC1 moves motor A) with a crank on ENC1; `expect` follows from line 13.
std::string scenario_text(const std::string& expect) {
  return "duration_s = 3\n"
         "[[board]]\nname = \"driver\"\nsketch = \"" +
         source_path("examples/StepASketch/StepASketch.ino") +
         "\"\n"
         "sockets = { A = { device = \"stepper\" }, B = { device = \"stepper\", microsteps = 4 } }\n"
         "[[device]]\nname = \"crank\"\ntype = \"test_crank\"\nboard = \"driver\"\nconnector = \"ENC1\"\n"
         "counts_per_s = -1200\nstop_s = 2\n" +
         expect;
}

std::vector<std::string> errors_of(const std::string& text) {
  std::vector<std::string> errors;
  for (const scenario::Diagnostic& error : scenario::parse_scenario(text, kFile).errors)
    errors.push_back(error.to_string());
  return errors;
}

const std::string kNeedsOneCheck =
    ":13: an [[expect]] needs one check: motor, pen_mm, strokes, bounds_mm, drawn_mm, z_mm, extruded_per_mm, traces, "
    "port, cable_counts_match, rejected, host, screen";

class TestExpectationKind : public ::testing::Test {
 protected:
  ScopedKind<DeviceRegistry> crank_{test_crank_kind()};
  ScopedKind<ExpectationRegistry> turns_{test_turns_kind()};
};

TEST(TestExpectationKindRegistry, IsUnknownUntilRegisteredAndGoneAfter) {
  ScopedKind<DeviceRegistry> crank(test_crank_kind());
  const std::string text = scenario_text("[[expect]]\n");
  EXPECT_EQ(find_expectation_kind("test_turns"), nullptr);
  EXPECT_EQ(errors_of(text), (std::vector<std::string>{kFile + kNeedsOneCheck + " or i2c_loop_pass_max_us"}));
  {
    ScopedKind<ExpectationRegistry> turns(test_turns_kind());
    EXPECT_EQ(find_expectation_kind("test_turns"), &test_turns_kind());
    EXPECT_EQ(errors_of(text),
              (std::vector<std::string>{kFile + kNeedsOneCheck + ", i2c_loop_pass_max_us or test_turns"}))
        << "the list names the new kind last";
  }
  EXPECT_EQ(find_expectation_kind("test_turns"), nullptr);
  EXPECT_EQ(errors_of(text), (std::vector<std::string>{kFile + kNeedsOneCheck + " or i2c_loop_pass_max_us"}));
}

TEST_F(TestExpectationKind, KeysAreReadIntoTheirSettings) {
  const scenario::Scenario read = parse(scenario_text("[[expect]]\ntest_turns = \"driver:B\"\nturns = -0.25\n"), kFile);
  ASSERT_EQ(read.expectations.size(), 1u);
  EXPECT_EQ(read.expectations[0].kind, &test_turns_kind());
  EXPECT_EQ(read.expectations[0].line, 13);
  const TestTurnsCheck* check = read.expectations[0].settings_as<TestTurnsCheck>();
  ASSERT_NE(check, nullptr);
  EXPECT_EQ(check->socket.board, "driver");
  EXPECT_EQ(check->socket.port, 'B');
  EXPECT_EQ(check->steps_per_turn, 4 * 200);  // microsteps = 4, 200 full steps (the default)
  EXPECT_EQ(check->turns, -0.25);
}

TEST_F(TestExpectationKind, KeysAreCheckedLikeTheBuiltInOnes) {
  // Lines: 13 [[expect]], 14 to 16 its keys.
  EXPECT_EQ(errors_of(scenario_text("[[expect]]\ntest_turns = \"driver:A\"\nturns = 2000\n")),
            (std::vector<std::string>{kFile + ":15: 'turns' must be in [-1,000, 1,000] turns, got 2,000"}));
  EXPECT_EQ(
      errors_of(scenario_text("[[expect]]\ntest_turns = \"driver:C\"\nturns = 1\n")),
      (std::vector<std::string>{kFile + ":14: 'test_turns' must name a stepper socket \"board:A\", got \"driver:C\""}));
  EXPECT_EQ(errors_of(scenario_text("[[expect]]\ntest_turns = \"driver:A\"\n")),
            (std::vector<std::string>{kFile + ":13: [[expect]] is missing required key 'turns'"}));
  EXPECT_EQ(errors_of(scenario_text("[[expect]]\ntest_turns = \"driver:A\"\nturns = 1\nsteps = 3\n")),
            (std::vector<std::string>{kFile + ":16: 'steps' only goes with 'motor'"}));
  EXPECT_EQ(errors_of(scenario_text("[[expect]]\nmotor = \"driver:A\"\nsteps = 3\nturns = 1\n")),
            (std::vector<std::string>{kFile + ":16: 'turns' only goes with 'test_turns'"}));
  EXPECT_EQ(
      errors_of(scenario_text("[[expect]]\nmotor = \"driver:A\"\ntest_turns = \"driver:A\"\n")),
      (std::vector<std::string>{kFile + ":15: an [[expect]] checks one thing, but has both 'motor' and 'test_turns'"}));
}

TEST_F(TestExpectationKind, ChecksTheEndOfARunUnderARealSketch) {
  // The crank turns knob 1 by −2400 counts in 2 s: StepASketch moves motor A −1920 microsteps
  // (tests/sim/kinds/test_only_kinds_test.cpp), −1920 / (16 × 200) = −0.6 of a turn.
  auto simulation = create(parse(scenario_text("[[expect]]\ntest_turns = \"driver:A\"\nturns = -0.6\n"
                                               "[[expect]]\ntest_turns = \"driver:A\"\nturns = 0.5\n"),
                                 kFile),
                           "test_expectation_kind", false);
  ASSERT_NE(simulation, nullptr);
  const SimulationReport report = simulation->finish();
  ASSERT_EQ(report.expectations.size(), 2u);
  EXPECT_TRUE(report.expectations[0].met) << report.expectations[0].message;
  EXPECT_EQ(report.expectations[0].message, kFile + ":13: motor driver:A turned -0.6000 turns (expected -0.6000)");
  EXPECT_FALSE(report.expectations[1].met);
  EXPECT_EQ(report.expectations[1].message, kFile + ":16: motor driver:A turned -0.6000 turns (expected 0.5000)");
}

}  // namespace
}  // namespace stepdance::sim::test
