// The simulator's CPU-load model: non-zero, deterministic, and growing with the sketch's graph.
#include "simulation_fixture.hpp"

namespace stepdance::sim::test {
namespace {

double average_load_percent(const std::string& example, const std::string& tag) {
  auto simulation = create(load(source_path("examples/" + example + "/scenario.toml")), tag, false);
  if (simulation == nullptr) return -1;
  simulation->finish();
  const StepdanceBoardStatsV1 stats = simulation->board("driver")->stats();
  if (stats.load_frames == 0 || stats.load_budget_cycles == 0) return -1;
  return 100.0 * static_cast<double>(stats.load_total_cycles) / static_cast<double>(stats.load_frames) /
         stats.load_budget_cycles;
}

// Step-A-Sketch runs 10 blocks every frame (2 encoders, CoreXY, the pen's PositionGenerator,
// 3 channels, 3 output ports): 10 × 155 modelled cycles of a 24,000-cycle frame.
TEST(CpuLoadModel, StepASketchCostsItsBlocks) {
  EXPECT_NEAR(average_load_percent("StepASketch", "load_step_a_sketch"), 100.0 * 10 * 155 / 24000, 1e-9);
}

// The Harmonograph adds a ScalingFilter2D and two start generators (13 blocks).
TEST(CpuLoadModel, ABiggerGraphCostsMore) {
  const double step_a_sketch = average_load_percent("StepASketch", "load_small");
  const double harmonograph = average_load_percent("Harmonograph", "load_large");
  EXPECT_GT(step_a_sketch, 0.0);
  EXPECT_NEAR(harmonograph, 100.0 * 13 * 155 / 24000, 1e-9);
  EXPECT_GT(harmonograph, step_a_sketch);
}

}  // namespace
}  // namespace stepdance::sim::test
