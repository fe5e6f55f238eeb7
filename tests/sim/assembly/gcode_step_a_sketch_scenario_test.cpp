// The G-code Step-A-Sketch example end to end: a scripted Grbl sender streams the rosette
// with character counting while a knob nudges the pen; every line acknowledged, motors exact.
#include <fstream>
#include <sstream>

#include "simulation_fixture.hpp"

namespace stepdance::sim::test {
namespace {

class GCodeStepASketchScenarioTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    simulation_ = create(load(source_path("examples/GCodeStepASketch")), "gcode_step_a_sketch").release();
    report_ = new SimulationReport(simulation_->finish());
  }
  static void TearDownTestSuite() {
    delete report_;
    delete simulation_;
  }
  static Simulation* simulation_;
  static SimulationReport* report_;
};
Simulation* GCodeStepASketchScenarioTest::simulation_ = nullptr;
SimulationReport* GCodeStepASketchScenarioTest::report_ = nullptr;

TEST_F(GCodeStepASketchScenarioTest, EveryExpectationOfTheExampleHolds) {
  ASSERT_EQ(report_->expectations.size(), 7u);
  for (const ExpectationResult& result : report_->expectations) EXPECT_TRUE(result.met) << result.message;
}

TEST_F(GCodeStepASketchScenarioTest, EveryLineOfTheFileIsAcknowledgedInOrder) {
  std::ifstream file(source_path("examples/GCodeStepASketch/rosette.gcode"));
  std::vector<std::string> lines;
  for (std::string line; std::getline(file, line);) lines.push_back(line);
  const HostClient* client = simulation_->host_client("driver");
  ASSERT_NE(client, nullptr);
  EXPECT_TRUE(client->completed()) << client->failure();
  EXPECT_EQ(client->acknowledged_lines(), lines.size());
  // The lines went out exactly as in the file, in order.
  size_t next = 0;
  for (const HostClient::Entry& entry : client->transcript()) {
    if (entry.from_host && next < lines.size() && entry.text == lines[next]) ++next;
  }
  EXPECT_EQ(next, lines.size());
}

TEST_F(GCodeStepASketchScenarioTest, MotorsEndAtHomePlusTheKnobsNudge) {
  // Pen at (5, 0) mm on CoreXY with 80 microsteps/mm through inverted channels (as the
  // original's gcode_stepasketch): a = −80 (x + y), b = −80 (x − y), counted per DIR-high step.
  EXPECT_EQ(simulation_->stepper("driver", 'A')->position_steps(), -400);
  EXPECT_EQ(simulation_->stepper("driver", 'B')->position_steps(), -400);
  // Z4 (pen up) at 50 servo steps per mm.
  EXPECT_EQ(simulation_->board("driver")->ports().sent(2)[SIGNAL_E].forward -
                static_cast<int64_t>(simulation_->board("driver")->ports().sent(2)[SIGNAL_E].reverse),
            200);
}

}  // namespace
}  // namespace stepdance::sim::test
