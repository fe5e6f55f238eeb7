// Same scenario, same sketches: byte-identical output files, run after run.
#include "simulation_fixture.hpp"

namespace stepdance::sim::test {
namespace {

/// Step-A-Sketch for three seconds with every output on: knobs, a bouncing button, VCD, CSV.
scenario::Scenario busy_scenario() {
  const std::string text = R"(
duration_s = 3
seed = 7

[[board]]
name = "driver"
sketch = "StepASketch.ino"

[board.sockets]
A = { device = "stepper" }
B = { device = "stepper" }
C = { device = "servo" }

[machine]
type = "corexy_plotter"
board = "driver"

[[device]]
name = "knob_x"
type = "encoder"
board = "driver"
connector = "ENC1"

[[device]]
name = "knob_y"
type = "encoder"
board = "driver"
connector = "ENC2"

[[device]]
name = "pen"
type = "button"
board = "driver"
connector = "D1"
bounce_ms = 5

[[at]]
time_s = 0.2
click = "pen"

[[at]]
time_s = 0.6
turn = "knob_x"
counts = 2500
over_s = 1.5

[[at]]
time_s = 0.9
turn = "knob_y"
counts = 1800
over_s = 1.2

[[at]]
time_s = 2.5
click = "pen"

[output]
pen_up_travel = true
vcd = "wire.vcd"
vcd_ports = ["driver:OUT_A", "driver:OUT_B", "driver:OUT_C"]
csv = "positions.csv"
csv_interval_ms = 5
)";
  return parse(text, source_path("examples/StepASketch/determinism_test.toml"));
}

// The summary's last line before the closing brace holds the wall time, which may differ.
std::string without_wall_time(const std::string& summary) {
  const size_t wall = summary.find("\"wall_time_s\"");
  return wall == std::string::npos ? summary : summary.substr(0, wall);
}

TEST(DeterminismTest, TwoRunsWriteByteIdenticalFiles) {
  const scenario::Scenario scenario = busy_scenario();
  std::vector<std::string> first_files;
  for (const char* name : {"determinism_1", "determinism_2"}) {
    auto simulation = create(scenario, name);
    const SimulationReport report = simulation->finish();
    if (first_files.empty()) first_files = report.files;
  }
  ASSERT_EQ(first_files.size(), 5u);  // VCD, CSV, SVG, PNG, summary
  for (const std::string& path : first_files) {
    const std::string name = std::filesystem::path(path).filename().string();
    const std::string first = read_file(test_output_dir("determinism_1") + "/" + name);
    const std::string second = read_file(test_output_dir("determinism_2") + "/" + name);
    ASSERT_FALSE(first.empty()) << name;
    if (name == "summary.json") {
      EXPECT_EQ(without_wall_time(first), without_wall_time(second));
    } else {
      EXPECT_TRUE(first == second) << name << " differs between runs";
    }
  }
}

}  // namespace
}  // namespace stepdance::sim::test
