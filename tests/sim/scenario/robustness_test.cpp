// The parser never throws or crashes: every prefix of a valid scenario gives a result.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "scenario/load_scenario.hpp"

namespace stepdance::sim::scenario {
namespace {

const std::string kFull = std::string(STEPDANCE_SOURCE_DIR) + "/tests/sim/scenario/fixtures/full/scenario.toml";

TEST(ScenarioRobustness, EveryPrefixOfTheFullExampleParsesWithoutThrowing) {
  std::ifstream in(kFull);
  std::ostringstream text;
  text << in.rdbuf();
  const std::string full = text.str();
  ASSERT_GT(full.size(), 1000u);
  size_t valid = 0;
  for (size_t length = 0; length <= full.size(); ++length) {
    LoadResult result;
    EXPECT_NO_THROW(result = parse_scenario(full.substr(0, length), kFull)) << length;
    for (const Diagnostic& error : result.errors) {
      ASSERT_GE(error.line, 1) << length;
      ASSERT_FALSE(error.message.empty()) << length;
    }
    if (result.ok()) ++valid;
  }
  EXPECT_GT(valid, 0u);  // at least the whole file
}

TEST(ScenarioRobustness, BinaryGarbageIsASyntaxError) {
  const LoadResult result = parse_scenario(std::string("\x00\xff[[[\n= =\n", 10), kFull);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.errors.size(), 1u);
}

}  // namespace
}  // namespace stepdance::sim::scenario
