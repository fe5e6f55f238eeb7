// The five-bar arm's stop keys: the original pantograph's stops by default, others when given,
// and only stops that leave the arm's home (−60°, 240°) inside the turn they allow.
#include <gtest/gtest.h>

#include <string>

#include "kinds/devices/five_bar_arm.hpp"
#include "scenario/load_scenario.hpp"

namespace stepdance::sim::scenario {
namespace {

const std::string kFile = std::string(STEPDANCE_SOURCE_DIR) + "/tests/sim/scenario/fixtures/full/inline.toml";

/// A Driver Module with an arm on ENC1/ENC2; `keys` are added to the arm (from line 13 on).
std::string arm_scenario(const std::string& keys) {
  return "duration_s = 5\n"
         "[[board]]\n"
         "name = \"driver\"\n"
         "sketch = \"../sketches/driver.ino\"\n"
         "[[device]]\n"
         "name = \"arm\"\n"
         "type = \"five_bar_arm\"\n"
         "board = \"driver\"\n"
         "connector = \"ENC1\"\n"
         "left_connector = \"ENC2\"\n"
         "path_mm = [[0, 150]]\n"
         "speed_mm_per_s = 10\n" +
         keys;
}

TEST(FiveBarArmStops, DefaultToTheOriginalPantographsLatches) {
  const LoadResult result = parse_scenario(arm_scenario(""), kFile);
  ASSERT_TRUE(result.ok()) << result.error_text();
  EXPECT_EQ(result.scenario.devices[0].settings_as<FiveBarArmConfig>()->right_min_deg, -60);
  EXPECT_EQ(result.scenario.devices[0].settings_as<FiveBarArmConfig>()->left_max_deg, 240);
}

TEST(FiveBarArmStops, AreReadWhenGiven) {
  const LoadResult result = parse_scenario(arm_scenario("right_min_deg = -90\nleft_max_deg = 270.5\n"), kFile);
  ASSERT_TRUE(result.ok()) << result.error_text();
  EXPECT_EQ(result.scenario.devices[0].settings_as<FiveBarArmConfig>()->right_min_deg, -90);
  EXPECT_EQ(result.scenario.devices[0].settings_as<FiveBarArmConfig>()->left_max_deg, 270.5);
}

// A right stop above −60° or a left one below 240° would hold the arm's home past its stop; one
// more than a turn away would be the same stop met from the other side.
TEST(FiveBarArmStops, MustLeaveHomeInsideTheTurnTheyAllow) {
  const LoadResult result = parse_scenario(arm_scenario("right_min_deg = -50\nleft_max_deg = 239\n"), kFile);
  ASSERT_EQ(result.errors.size(), 2u);
  EXPECT_EQ(result.errors[0].to_string(), kFile + ":13: 'right_min_deg' must be in [-420, -60] °, got -50");
  EXPECT_EQ(result.errors[1].to_string(), kFile + ":14: 'left_max_deg' must be in [240, 600] °, got 239");
  const LoadResult far = parse_scenario(arm_scenario("right_min_deg = -421\nleft_max_deg = 601\n"), kFile);
  EXPECT_EQ(far.errors.size(), 2u);
}

TEST(FiveBarArmStops, BelongToTheArmOnly) {
  const std::string text =
      "duration_s = 5\n[[board]]\nname = \"driver\"\nsketch = \"../sketches/driver.ino\"\n"
      "[[device]]\nname = \"knob\"\ntype = \"encoder\"\nboard = \"driver\"\nconnector = \"ENC1\"\nleft_max_deg = 240\n";
  const LoadResult result = parse_scenario(text, kFile);
  ASSERT_EQ(result.errors.size(), 1u);
  EXPECT_EQ(result.errors[0].to_string(), kFile + ":10: 'left_max_deg' does not apply to an encoder");
}

}  // namespace
}  // namespace stepdance::sim::scenario
