// The Step-A-Sketch example scenario end to end: exact motor steps, pen position, strokes, pulses.
#include "simulation_fixture.hpp"

namespace stepdance::sim::test {
namespace {

class StepASketchScenarioTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    simulation_ = create(load(source_path("examples/StepASketch")), "step_a_sketch").release();
    report_ = new SimulationReport(simulation_->finish());
  }
  static void TearDownTestSuite() {
    delete report_;
    delete simulation_;
  }
  static Simulation* simulation_;
  static SimulationReport* report_;
};
Simulation* StepASketchScenarioTest::simulation_ = nullptr;
SimulationReport* StepASketchScenarioTest::report_ = nullptr;

TEST_F(StepASketchScenarioTest, EveryExpectationOfTheExampleHolds) {
  ASSERT_EQ(report_->expectations.size(), 4u);
  for (const ExpectationResult& result : report_->expectations) EXPECT_TRUE(result.met) << result.message;
  EXPECT_EQ(report_->simulated_ns, 42 * kSecond);
}

TEST_F(StepASketchScenarioTest, MotorsEndAtTheHouseWindowCorner) {
  // Pen (110, 85) mm through inverted channels: a = −80 × (110 + 85), b = −80 × (110 − 85)
  // microsteps, counted +1 per step with DIR high.
  EXPECT_EQ(simulation_->stepper("driver", 'A')->position_steps(), -15600);
  EXPECT_EQ(simulation_->stepper("driver", 'B')->position_steps(), -2000);
  // Every step the board sent reached an enabled driver. The knobs' path has 52,000 steps of a
  // towards the page's +x/+y (DIR low) and 36,400 back.
  EXPECT_EQ(simulation_->stepper("driver", 'A')->forward_steps(), 36400u);
  EXPECT_EQ(simulation_->stepper("driver", 'A')->reverse_steps(), 52000u);
  EXPECT_EQ(simulation_->stepper("driver", 'A')->ignored_steps(), 0u);
  EXPECT_EQ(simulation_->board("driver")->ports().sent(0)[SIGNAL_E].forward, 36400u);
  EXPECT_EQ(simulation_->board("driver")->ports().sent(0)[SIGNAL_E].reverse, 52000u);
}

TEST_F(StepASketchScenarioTest, PenDrawsFourStrokesAndEndsUp) {
  const Machine& machine = *simulation_->machine();
  EXPECT_DOUBLE_EQ(machine.pen_position().x_mm, 110.0);
  EXPECT_DOUBLE_EQ(machine.pen_position().y_mm, 85.0);
  EXPECT_FALSE(machine.pen_down());
  ASSERT_EQ(machine.strokes().size(), 4u);  // walls, roof, door, window
  // The walls: a closed 80 mm square from the bottom-left corner (100, 150).
  const Polyline& walls = machine.strokes()[0];
  EXPECT_EQ(walls.front(), (PenPoint{100, 150}));
  EXPECT_EQ(walls.back(), (PenPoint{100, 150}));
  EXPECT_EQ(walls.size(), 5u);
  EXPECT_EQ(machine.stats().travel_excursions, 0u);
}

TEST_F(StepASketchScenarioTest, PenServoMovedFourTimesEachWay) {
  // Four clicks down (−200 from +0 or +200) and four up: 200 + 7 × 400 = 3000 servo steps.
  const PulseCounts& pen = simulation_->board("driver")->ports().sent(2);
  EXPECT_EQ(pen[SIGNAL_E].forward, 1600u);
  EXPECT_EQ(pen[SIGNAL_E].reverse, 1400u);
  EXPECT_EQ(simulation_->servo("driver", 'C')->position_steps(), 200);
}

TEST_F(StepASketchScenarioTest, WritesTheDrawingAndTheSummary) {
  ASSERT_EQ(report_->files.size(), 3u);
  EXPECT_NE(read_file(test_output_dir("step_a_sketch") + "/drawing.svg").find("<polyline"), std::string::npos);
  EXPECT_EQ(read_file(test_output_dir("step_a_sketch") + "/drawing.png").substr(1, 3), "PNG");
  EXPECT_NE(read_file(test_output_dir("step_a_sketch") + "/summary.json").find("\"strokes\": 4"), std::string::npos);
}

}  // namespace
}  // namespace stepdance::sim::test
