// The original library's public names, as its example sketches use them, through the sketch builder.
//
// Each folder under tests/sim/assembly/fixtures/original_api/ is a compile-only sketch of our own
// that uses names and signatures the original's 33 compatible examples use (see
// docs/compatibility.md). A fixture whose first line is "// waits-for: NAME..." needs blocks that
// have not landed yet: while the compiler's only complaints are that those classes or members do
// not exist (and what follows from that), the test is skipped with that reason; once they exist,
// the fixture must compile like the others.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "board/loader/sketch_builder.hpp"

namespace stepdance::sim {
namespace {

namespace fs = std::filesystem;

const fs::path kFixtures = fs::path(STEPDANCE_SOURCE_DIR) / "tests/sim/assembly/fixtures/original_api";
const std::vector<std::string> kFixtureNames = {"CoreDriver", "CoreBasic",  "CoreAdditions", "Generators",
                                                "Filters",    "Kinematics", "Recording",     "Homing"};

// The names after "// waits-for:" on the fixture's first line.
std::vector<std::string> waits_for(const std::string& name) {
  std::ifstream in(kFixtures / name / (name + ".ino"));
  std::string first_line;
  std::getline(in, first_line);
  const std::string marker = "// waits-for:";
  std::vector<std::string> names;
  if (first_line.rfind(marker, 0) != 0) return names;
  std::istringstream words(first_line.substr(marker.size()));
  for (std::string word; words >> word;) names.push_back(word);
  return names;
}

// What the compiler says when `name` (Class or Class::member) does not exist, quoted as in a
// UTF-8 locale (‘name’) or in the C locale ('name').
std::vector<std::string> missing_messages(const std::string& name) {
  std::vector<std::string> messages;
  const std::size_t colons = name.find("::");
  for (const auto& [open, close] : {std::pair<std::string, std::string>{"\u2018", "\u2019"}, {"'", "'"}}) {
    messages.push_back(colons == std::string::npos ? open + name + close + " does not name a type"
                                                   : "has no member named " + open + name.substr(colons + 2) + close);
  }
  return messages;
}

// True if every error is about a waited-for name missing, or a consequence ("was not declared"),
// and at least one is about a waited-for name.
bool only_waiting(const std::string& output, const std::vector<std::string>& waited) {
  bool any_waited = false;
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);) {
    if (line.find(" error: ") == std::string::npos) continue;
    bool explained = line.find("was not declared in this scope") != std::string::npos;
    for (const std::string& name : waited) {
      for (const std::string& message : missing_messages(name)) {
        if (line.find(message) != std::string::npos) explained = any_waited = true;
      }
    }
    if (!explained) return false;
  }
  return any_waited;
}

class OriginalApiFixture : public ::testing::TestWithParam<std::string> {};

TEST_P(OriginalApiFixture, CompilesThroughTheSketchBuilder) {
  const std::string name = GetParam();
  const SketchBuild build = SketchBuilder(STEPDANCE_BUILD_DIR "/sketch-cache").build((kFixtures / name).string());
  if (build.ok) return;
  const std::vector<std::string> waited = waits_for(name);
  if (!waited.empty() && only_waiting(build.error, waited)) {
    GTEST_SKIP() << name << " waits for blocks that have not landed: " << testing::PrintToString(waited);
  }
  FAIL() << build.error;
}

INSTANTIATE_TEST_SUITE_P(OriginalApi, OriginalApiFixture, ::testing::ValuesIn(kFixtureNames),
                         [](const testing::TestParamInfo<std::string>& param) { return param.param; });

TEST(OriginalApiFixtures, EveryFixtureFolderIsBuilt) {
  std::set<std::string> folders;
  for (const auto& entry : fs::directory_iterator(kFixtures)) {
    if (entry.is_directory()) folders.insert(entry.path().filename().string());
  }
  EXPECT_EQ(folders, std::set<std::string>(kFixtureNames.begin(), kFixtureNames.end()));
}

TEST(OriginalApiFixtures, AWaitedNameOnlyExcusesItsOwnAbsence) {
  const std::vector<std::string> waited = {"VelocityGenerator", "AnalogInput::last_value_raw"};
  EXPECT_TRUE(
      only_waiting("a.ino:3:1: error: \u2018VelocityGenerator\u2019 does not name a type\n"
                   "a.ino:9:3: error: \u2018spin\u2019 was not declared in this scope\n",
                   waited));
  EXPECT_TRUE(
      only_waiting("a.ino:4:9: error: \u2018class stepdance::AnalogInput\u2019 has no member named "
                   "\u2018last_value_raw\u2019\n",
                   waited));
  EXPECT_TRUE(only_waiting("a.ino:3:1: error: 'VelocityGenerator' does not name a type\n", waited));  // C locale
  // The class exists now, but a member the sketches use does not: a real failure.
  EXPECT_FALSE(
      only_waiting("a.ino:5:9: error: \u2018class stepdance::VelocityGenerator\u2019 has no member named "
                   "\u2018speed_units_per_sec\u2019\n",
                   waited));
  // Only consequences, no waited-for name: something else is wrong.
  EXPECT_FALSE(only_waiting("a.ino:9:3: error: \u2018spin\u2019 was not declared in this scope\n", waited));
}

}  // namespace
}  // namespace stepdance::sim
