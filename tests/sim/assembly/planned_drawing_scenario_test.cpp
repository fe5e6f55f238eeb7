// The PlannedDrawing example: the sketch's own TimeBasedInterpolator draws a star and a
// 1,000-segment spiral; the feed knob pauses the plot smoothly and resumes it exactly.
#include <cmath>

#include "simulation_fixture.hpp"

namespace stepdance::sim::test {
namespace {

PenPoint pen_at(Simulation& simulation, double seconds) {
  simulation.run_until(from_seconds(seconds));
  return simulation.machine()->pen_position();
}

TEST(PlannedDrawingScenario, TheFeedKnobPausesThePenOnThePathAndResumes) {
  auto simulation = create(load(source_path("examples/PlannedDrawing/pause.toml")), "planned_drawing_pause", false);
  // Override 0 from t = 3 s: stopping from 60 mm/s at 1500 mm/s² takes 40 ms.
  const PenPoint before = pen_at(*simulation, 2.9);
  const PenPoint paused = pen_at(*simulation, 3.2);
  const PenPoint still = pen_at(*simulation, 5.9);
  EXPECT_GT(std::hypot(paused.x_mm - before.x_mm, paused.y_mm - before.y_mm), 1.0);  // it was drawing
  EXPECT_EQ(paused, still);                                                          // then it waited
  const PenPoint resumed = pen_at(*simulation, 6.5);
  EXPECT_GT(std::hypot(resumed.x_mm - still.x_mm, resumed.y_mm - still.y_mm), 1.0);  // and went on
  const SimulationReport report = simulation->finish();
  for (const ExpectationResult& result : report.expectations) EXPECT_TRUE(result.met) << result.message;
}

}  // namespace
}  // namespace stepdance::sim::test
