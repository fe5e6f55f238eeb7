// A reply pattern that backtracking matchers take exponential time over: `^echo: (a+)+$` on the
// echo of 48 'a's and a '!' (libstdc++'s std::regex tries every way of splitting the 'a's, about
// 2^48 of them, and never came back). RE2 matches in time linear in the line, so the wait fails
// by its timeout like any other unmatched wait, and a pattern that does match still matches.
#include <chrono>
#include <string>

#include "simulation_fixture.hpp"

namespace stepdance::sim::test {
namespace {

std::string scenario_text(const std::string& pattern) {
  return "duration_s = 0.3\n"
         "[[board]]\nname = \"board\"\nsketch = \"HostFeatures.ino\"\n"
         "[board.sockets]\nA = { device = \"stepper\" }\n"
         "[[host]]\nboard = \"board\"\n"
         "[[host.step]]\nwait = \"^setup done\"\ntimeout_s = 0.1\n"
         "[[host.step]]\nsend = \"" +
         std::string(48, 'a') +
         "!\\n\"\n"
         "[[host.step]]\nwait = '" +
         pattern +
         "'\ntimeout_s = 0.05\n"
         "[output]\nsvg = \"\"\npng = \"\"\n";
}

/// Runs the scenario waiting for `pattern`; the client and how long the run took on the wall.
struct PatternRun {
  std::unique_ptr<Simulation> simulation;
  const HostClient* client = nullptr;
  double wall_s = 0;
};

PatternRun run(const std::string& pattern, const std::string& name) {
  PatternRun result;
  const auto started = std::chrono::steady_clock::now();
  result.simulation =
      create(parse(scenario_text(pattern), source_path("tests/sim/assembly/fixtures/HostFeatures/scenario.toml")), name,
             false);
  if (result.simulation == nullptr) return result;
  result.simulation->finish();
  result.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  result.client = result.simulation->host_client("board");
  return result;
}

TEST(HostClientPatternsTest, ANestedRepeatOverALongLineFailsByItsTimeoutNotForEver) {
  const PatternRun nested = run("^echo: (a+)+$", "host_client_patterns_nested");
  ASSERT_NE(nested.client, nullptr);
  EXPECT_FALSE(nested.client->completed());
  EXPECT_NE(nested.client->failure().find("^echo: (a+)+$"), std::string::npos) << nested.client->failure();
  EXPECT_LT(nested.wall_s, 10.0);  // with the sketch build cached, well under a second
}

TEST(HostClientPatternsTest, TheSamePatternStillMatchesWhatItDescribes) {
  const PatternRun matching = run("^echo: (a+)+!$", "host_client_patterns_matching");
  ASSERT_NE(matching.client, nullptr);
  EXPECT_TRUE(matching.client->completed()) << matching.client->failure();
}

}  // namespace
}  // namespace stepdance::sim::test
