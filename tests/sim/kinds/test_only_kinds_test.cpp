// The map of docs/architecture.md ("Where things go"), proved: a device kind and a machine kind
// defined only in this folder (test_crank.hpp, test_gauge.hpp) are read from a scenario file,
// checked like the built-in ones, built and run under a real sketch — with no other file edited.
#include <gtest/gtest.h>

#include <string>

#include "sim/assembly/simulation_fixture.hpp"
#include "sim/kinds/test_crank.hpp"
#include "sim/kinds/test_gauge.hpp"

namespace stepdance::sim::test {
namespace {

const std::string kFile = "/tmp/test_only_kinds/scenario.toml";

/// StepASketch (knob 1 on ENC1 moves motor A) with a crank on ENC1 and a gauge on socket A.
std::string scenario_text(const std::string& crank_keys, const std::string& machine_keys = "") {
  return "duration_s = 3\n"
         "[[board]]\nname = \"driver\"\nsketch = \"" +
         source_path("examples/StepASketch/StepASketch.ino") +
         "\"\n"
         "sockets = { A = { device = \"stepper\" }, B = { device = \"stepper\" } }\n"
         "[machine]\ntype = \"test_gauge\"\nboard = \"driver\"\n" +
         machine_keys +
         "[[device]]\nname = \"crank\"\ntype = \"test_crank\"\nboard = \"driver\"\nconnector = \"ENC1\"\n" + crank_keys;
}

std::vector<std::string> errors_of(const std::string& text) {
  std::vector<std::string> errors;
  for (const scenario::Diagnostic& error : scenario::parse_scenario(text, kFile).errors)
    errors.push_back(error.to_string());
  return errors;
}

class TestOnlyKinds : public ::testing::Test {
 protected:
  ScopedKind<DeviceRegistry> crank_{test_crank_kind()};
  ScopedKind<MachineRegistry> gauge_{test_gauge_kind()};
};

TEST(TestOnlyKindsRegistry, AreUnknownUntilRegisteredAndGoneAfter) {
  EXPECT_EQ(find_device_kind("test_crank"), nullptr);
  EXPECT_EQ(find_machine_kind("test_gauge"), nullptr);
  {
    ScopedKind<DeviceRegistry> crank(test_crank_kind());
    ScopedKind<MachineRegistry> gauge(test_gauge_kind());
    EXPECT_EQ(find_device_kind("test_crank"), &test_crank_kind());
    EXPECT_EQ(find_machine_kind("test_gauge"), &test_gauge_kind());
    EXPECT_EQ(machine_kind_names(), "\"corexy_plotter\", \"cartesian\", \"polar\" or \"test_gauge\"");
  }
  EXPECT_EQ(find_device_kind("test_crank"), nullptr);
  EXPECT_EQ(machine_kind_names(), "\"corexy_plotter\", \"cartesian\" or \"polar\"");
}

TEST_F(TestOnlyKinds, UnknownTypeMessagesListThem) {
  const std::vector<std::string> errors = errors_of("duration_s = 1\n[[board]]\nname = \"b\"\nsketch = \"" +
                                                    source_path("examples/StepASketch/StepASketch.ino") +
                                                    "\"\n[[device]]\nname = \"d\"\ntype = \"lever\"\nboard = \"b\"\n"
                                                    "connector = \"ENC1\"\n");
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0], kFile +
                           ":7: 'type' must be \"encoder\", \"potentiometer\", \"button\", \"limit_switch\", "
                           "\"pendulum\", \"five_bar_arm\", \"oled\", \"twist\" or \"test_crank\", got \"lever\"");
}

TEST_F(TestOnlyKinds, KeysAreReadIntoTheirSettings) {
  const scenario::Scenario read =
      parse(scenario_text("counts_per_s = -1200\nstop_s = 2\n", "steps_per_mm = 40\n"), kFile);
  ASSERT_EQ(read.devices.size(), 1u);
  EXPECT_EQ(read.devices[0].kind, &test_crank_kind());
  ASSERT_NE(read.devices[0].settings_as<TestCrankConfig>(), nullptr);
  EXPECT_EQ(read.devices[0].settings_as<TestCrankConfig>()->counts_per_s, -1200);
  EXPECT_EQ(read.devices[0].settings_as<TestCrankConfig>()->stop_s, 2);
  ASSERT_TRUE(read.machine.has_value());
  EXPECT_EQ(read.machine->kind, &test_gauge_kind());
  EXPECT_EQ(read.machine->settings_as<TestGaugeConfig>()->steps_per_mm, 40);
}

TEST_F(TestOnlyKinds, KeysAreCheckedLikeTheBuiltInOnes) {
  // Lines: 9 steps_per_mm, 11 [[device]], 16 counts_per_s, 17 stop_s, 18 bounce_ms.
  EXPECT_EQ(errors_of(scenario_text("counts_per_s = 200000\nstop_s = 4\nbounce_ms = 2\n",
                                    "steps_per_mm = 0\nmotor = \"B\"\n")),
            (std::vector<std::string>{
                kFile + ":9: 'steps_per_mm' must be in (0, 1,000] steps/mm, got 0",
                kFile + ":16: 'counts_per_s' must be in [-100,000, 100,000] counts/s, got 200,000",
                kFile + ":17: 'stop_s' must be in [0, 3] s, got 4",
                kFile + ":18: 'bounce_ms' does not apply to a test crank",
            }));
  EXPECT_EQ(errors_of(scenario_text("")),
            (std::vector<std::string>{kFile + ":9: [[device]] is missing required key 'counts_per_s'"}));
}

TEST_F(TestOnlyKinds, ItsKeysDoNotApplyToOtherKinds) {
  const std::string text = "duration_s = 1\n[[board]]\nname = \"b\"\nsketch = \"" +
                           source_path("examples/StepASketch/StepASketch.ino") +
                           "\"\n[[device]]\nname = \"d\"\ntype = \"encoder\"\nboard = \"b\"\nconnector = \"ENC1\"\n"
                           "counts_per_s = 5\n";
  EXPECT_EQ(errors_of(text), (std::vector<std::string>{kFile + ":10: 'counts_per_s' does not apply to an encoder"}));
}

TEST_F(TestOnlyKinds, RunUnderARealSketch) {
  // The crank turns knob 1 by −2400 counts in 2 s: StepASketch moves its x 24 mm, motor A
  // −80 × 24 steps (its channels are inverted), which the gauge shows as x = −24 mm.
  auto simulation = create(parse(scenario_text("counts_per_s = -1200\nstop_s = 2\n") +
                                     "[[expect]]\npen_mm = [-24, 0]\n[[expect]]\nmotor = \"driver:A\"\nsteps = -1920\n",
                                 kFile),
                           "test_only_kinds", false);
  ASSERT_NE(simulation, nullptr);
  const SimulationReport report = simulation->finish();
  ASSERT_EQ(report.expectations.size(), 2u);
  for (const ExpectationResult& result : report.expectations) EXPECT_TRUE(result.met) << result.message;
  const TestCrank* crank = model_of<TestCrank>(simulation->device("crank"));
  ASSERT_NE(crank, nullptr);
  EXPECT_EQ(crank->count_at(3 * kSecond), -2400);
  EXPECT_EQ(simulation->machine()->axis_mm(MachineAxis::kX), -24.0);
}

}  // namespace
}  // namespace stepdance::sim::test
