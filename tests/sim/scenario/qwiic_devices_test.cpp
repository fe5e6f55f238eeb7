// Scenario keys of the QWIIC devices (oled, twist) and their checks: what is accepted and the
// exact error for each bad value.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "kinds/devices/oled.hpp"
#include "kinds/expectations/i2c_loop_time.hpp"
#include "kinds/expectations/screen_text.hpp"
#include "scenario/load_scenario.hpp"

namespace stepdance::sim::scenario {
namespace {

const std::string kFile = std::string(STEPDANCE_SOURCE_DIR) + "/tests/sim/scenario/fixtures/full/inline.toml";

// Lines 1..4: a run and a Driver Module.
const std::string kDriver =
    "duration_s = 5\n"
    "[[board]]\n"
    "name = \"driver\"\n"
    "sketch = \"../sketches/driver.ino\"\n";

std::vector<std::string> errors_of(const std::string& text) {
  const LoadResult result = parse_scenario(kDriver + text, kFile);
  std::vector<std::string> errors;
  for (const Diagnostic& error : result.errors) errors.push_back(error.to_string());
  return errors;
}

std::string at(int line, const std::string& message) { return kFile + ":" + std::to_string(line) + ": " + message; }

TEST(QwiicDevices, ScreenAndKnobShareQwiic1WithDefaultAddresses) {
  const LoadResult result =
      parse_scenario(kDriver +
                         "[[device]]\nname = \"screen\"\ntype = \"oled\"\nboard = \"driver\"\nconnector = \"QWIIC1\"\n"
                         "snapshots_s = [1, 2.5]\n"
                         "[[device]]\nname = \"knob\"\ntype = \"twist\"\nboard = \"driver\"\nconnector = \"QWIIC1\"\n"
                         "[[at]]\ntime_s = 1\nturn = \"knob\"\ncounts = -3\n"
                         "[[at]]\ntime_s = 2\nclick = \"knob\"\n"
                         "[[expect]]\nscreen = \"screen\"\nrow = 2\nshows = \"X 1.00\"\n"
                         "[[expect]]\ni2c_loop_pass_max_us = 1000\nboard = \"driver\"\n",
                     kFile);
  ASSERT_TRUE(result.ok()) << result.error_text();
  const Scenario& scenario = result.scenario;
  EXPECT_EQ(scenario.device("screen")->i2c_address, 0x3C);
  EXPECT_EQ(scenario.device("knob")->i2c_address, 0x3F);
  EXPECT_EQ(scenario.device("screen")->settings_as<OledConfig>()->snapshots_s, (std::vector<double>{1, 2.5}));
  ASSERT_EQ(scenario.expectations.size(), 2u);
  EXPECT_EQ(scenario.expectations[0].kind, &screen_text_expectation());
  ASSERT_NE(scenario.expectations[0].settings_as<ScreenTextCheck>(), nullptr);
  EXPECT_EQ(scenario.expectations[0].settings_as<ScreenTextCheck>()->row, 2);
  EXPECT_EQ(scenario.expectations[1].kind, &i2c_loop_time_expectation());
  ASSERT_NE(scenario.expectations[1].settings_as<I2cLoopTimeCheck>(), nullptr);
  EXPECT_DOUBLE_EQ(scenario.expectations[1].settings_as<I2cLoopTimeCheck>()->max_us, 1000);
}

TEST(QwiicDevices, BadValuesAreReportedWhereTheyAre) {
  const std::vector<std::string> errors = errors_of(
      "[[device]]\nname = \"screen\"\ntype = \"oled\"\nboard = \"driver\"\nconnector = \"ENC1\"\n"  // 5..9
      "[[device]]\nname = \"a\"\ntype = \"twist\"\nboard = \"driver\"\nconnector = \"QWIIC0\"\n"    // 10..14
      "[[device]]\nname = \"b\"\ntype = \"oled\"\nboard = \"driver\"\nconnector = \"QWIIC0\"\n"     // 15..19
      "address = 63\nsnapshots_s = [9]\n"                                                           // 20..21
      "[[device]]\nname = \"c\"\ntype = \"twist\"\nboard = \"driver\"\nconnector = \"QWIIC1\"\n"    // 22..26
      "address = 200\n"                                                                             // 27
      "[[at]]\ntime_s = 1\nset = \"a\"\nposition = 0.5\n"                                           // 28..31
      "[[expect]]\nscreen = \"a\"\nshows = \"THIS LINE IS FAR TOO LONG\"\nrow = 4\n"                // 32..35
      "[[expect]]\ni2c_loop_pass_max_us = 0\nboard = \"ghost\"\n");                                 // 36..38
  const std::vector<std::string> expected = {
      at(9, "an OLED display cannot use connector ENC1 (use QWIIC0 or QWIIC1)"),
      at(20, "address 63 on QWIIC0 of board 'driver' is already used by device 'a'"),
      at(21, "'snapshots_s' must be a list of times in [0, 5] s"),
      at(27, "'address' must be a 7-bit I2C address in 0x08..0x77, got 200"),
      at(30, "'set' needs a potentiometer, but 'a' is a Qwiic Twist knob"),
      at(33, "'screen' must name an oled device, got 'a'"),
      at(34, "'shows' can be at most 21 characters (a row of the 128x32 screen)"),
      at(35, "'row' must be 0..3, got 4"),
      at(37, "'i2c_loop_pass_max_us' must be a time > 0 (µs)"),
      at(38, "unknown board 'ghost'"),
  };
  EXPECT_EQ(errors, expected);
}

}  // namespace
}  // namespace stepdance::sim::scenario
