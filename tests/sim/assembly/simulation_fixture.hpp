// Shared helpers for scenario tests: load a scenario, run it through the kernel API, read files.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "assembly/simulation.hpp"
#include "board/loader/sketch_builder.hpp"
#include "output/png_picture_writer.hpp"
#include "scenario/load_scenario.hpp"

namespace stepdance::sim::test {

/// Where tests cache compiled sketches and write their outputs.
inline const std::string kSketchCache = STEPDANCE_BUILD_DIR "/sketch-cache";
/// A folder for one test's files. CTest runs each test in its own process, in parallel, so the
/// process id keeps two tests of one suite apart.
inline std::string test_output_dir(const std::string& name) {
  return STEPDANCE_BUILD_DIR "/sim-test-out/" + name + "." + std::to_string(::getpid());
}
/// Removes this process's output folders when the test program ends (they can be large VCDs).
class OutputCleanup : public ::testing::Environment {
 public:
  void TearDown() override {
    std::error_code error;
    const std::string suffix = "." + std::to_string(::getpid());
    for (const auto& entry : std::filesystem::directory_iterator(STEPDANCE_BUILD_DIR "/sim-test-out", error)) {
      const std::string name = entry.path().filename().string();
      if (name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0) {
        std::filesystem::remove_all(entry.path(), error);
      }
    }
  }
};
inline ::testing::Environment* const kOutputCleanup = ::testing::AddGlobalTestEnvironment(new OutputCleanup);

inline std::string source_path(const std::string& relative) { return STEPDANCE_SOURCE_DIR "/" + relative; }

/// A scenario file, or text parsed as if it were `file` (relative paths resolve next to it).
inline scenario::Scenario load(const std::string& path) {
  const scenario::LoadResult loaded = scenario::load_scenario(path);
  EXPECT_TRUE(loaded.ok()) << loaded.error_text();
  return loaded.scenario;
}
inline scenario::Scenario parse(const std::string& text, const std::string& file) {
  const scenario::LoadResult loaded = scenario::parse_scenario(text, file);
  EXPECT_TRUE(loaded.ok()) << loaded.error_text();
  return loaded.scenario;
}

/// What the command line plugs into a simulation, for tests: the compiling board source
/// (caching in kSketchCache) and the PNG module.
inline void plug_test_hooks(SimulationOptions& options) {
  options.boards = std::make_shared<SketchBuilder>(kSketchCache);
  options.pictures = png_pictures();
}

/// Builds a simulation writing into test_output_dir(output_name) (emptied first).
inline std::unique_ptr<Simulation> create(const scenario::Scenario& scenario, const std::string& output_name,
                                          bool write_vcd = true) {
  SimulationOptions options;
  plug_test_hooks(options);
  options.output_directory = test_output_dir(output_name);
  options.write_vcd = write_vcd;
  std::filesystem::remove_all(*options.output_directory);
  SimulationError error;
  auto simulation = Simulation::create(scenario, options, error);
  EXPECT_NE(simulation, nullptr) << error.message;
  return simulation;
}

/// Scenario TOML for board "driver" running examples/GCodeStepASketch on a CoreXY plotter.
inline std::string gcode_step_a_sketch_board() {
  return "[[board]]\nname = \"driver\"\nsketch = \"" + source_path("examples/GCodeStepASketch/GCodeStepASketch.ino") +
         "\"\nmodule = \"driver\"\n"
         "sockets = { A = { device = \"stepper\", microsteps = 16 }, B = { device = \"stepper\", microsteps = 16 }, "
         "C = { device = \"servo\" } }\n"
         "[machine]\ntype = \"corexy_plotter\"\nboard = \"driver\"\n";
}

/// A file's bytes ("" if missing).
inline std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

}  // namespace stepdance::sim::test
