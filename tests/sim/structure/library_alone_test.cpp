// The simulator library on its own, as the WebAssembly page will link it: no compiler, no PNG
// module. This program links only stepdance_sim (CMake: stepdance_sim_structure_tests), so it
// building at all shows the library needs nothing of the command line's.
#include <gtest/gtest.h>

#include <string>

#include "assembly/simulation.hpp"
#include "scenario/load_scenario.hpp"

namespace stepdance::sim {
namespace {

/// A board source with no boards: every sketch is refused with the same words.
class NoBoards : public BoardSource {
 public:
  SketchBuild build(const std::string& sketch_path) const override {
    SketchBuild build;
    build.error = "no precompiled board for " + sketch_path;
    return build;
  }
};

/// One Driver Module running the Step-A-Sketch example (the reader checks that the sketch
/// exists), writing no file.
const std::string kSketch = STEPDANCE_SOURCE_DIR "/examples/StepASketch/StepASketch.ino";
const std::string kScenario =
    "duration_s = 1\n"
    "[[board]]\nname = \"driver\"\nsketch = \"" +
    kSketch +
    "\"\nmodule = \"driver\"\n"
    "[output]\nsvg = \"\"\npng = \"\"\nsummary = \"\"\nvcd = \"\"\ncsv = \"\"\n";

scenario::Scenario scenario_in(const std::string& file) {
  const scenario::LoadResult loaded = scenario::parse_scenario(kScenario, file);
  EXPECT_TRUE(loaded.ok()) << loaded.error_text();
  return loaded.scenario;
}

TEST(SimulatorLibraryAlone, TheBoardSourceItIsGivenAnswersForEachSketch) {
  SimulationOptions options;
  options.boards = std::make_shared<NoBoards>();
  SimulationError error;
  const auto simulation = Simulation::create(scenario_in("/nowhere/scenario.toml"), options, error);
  EXPECT_EQ(simulation, nullptr);
  EXPECT_EQ(error.kind, SimulationError::kBadInput);
  // The board's table starts on the scenario's line 2.
  EXPECT_EQ(error.message, "/nowhere/scenario.toml:2: board 'driver': no precompiled board for " + kSketch);
}

TEST(SimulatorLibraryAlone, WithoutABoardSourceNothingIsBuilt) {
  SimulationError error;
  const auto simulation = Simulation::create(scenario_in("/nowhere/scenario.toml"), SimulationOptions{}, error);
  EXPECT_EQ(simulation, nullptr);
  EXPECT_EQ(error.kind, SimulationError::kFailure);
  EXPECT_EQ(error.message, "no board source: this simulation cannot compile or load sketches");
}

}  // namespace
}  // namespace stepdance::sim
