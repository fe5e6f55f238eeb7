// The board runtime inside a sketch: delay(), Serial input and output, the SD card, faults.
#include "simulation_fixture.hpp"

namespace stepdance::sim::test {
namespace {

const char* const kScenario = R"(
duration_s = 0.5

[[board]]
name = "board"
sketch = "HostFeatures.ino"

[board.sockets]
A = { device = "stepper" }

[[at]]
time_s = 0.1
serial = "board"
text = "hello\n"

[[at]]
time_s = 0.12
serial = "board"
text = "warn\nwarn\nwarn\n"

[[at]]
time_s = 0.2
serial = "board"
text = "fault\n"

[output]
svg = ""
png = ""
)";

class BoardRuntimeTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const scenario::Scenario scenario =
        parse(kScenario, source_path("tests/sim/assembly/fixtures/HostFeatures/scenario.toml"));
    simulation_ = create(scenario, "board_runtime");
    ASSERT_NE(simulation_, nullptr);
    board_ = simulation_->board("board");
    board_->console().on_line([this](const std::string& line) { lines_.push_back(line); });
  }
  std::unique_ptr<Simulation> simulation_;
  SimBoard* board_ = nullptr;
  std::vector<std::string> lines_;
};

TEST_F(BoardRuntimeTest, DelayInSetupLetsBoardTimePass) {
  simulation_->run_until(10 * kMillisecond);
  ASSERT_FALSE(lines_.empty());
  EXPECT_EQ(lines_.front(), "setup done at ms 5");
}

TEST_F(BoardRuntimeTest, SerialActionsReachTheSketch) {
  simulation_->run_until(150 * kMillisecond);
  ASSERT_EQ(lines_.size(), 2u);
  EXPECT_EQ(lines_[1], "echo: hello");
}

TEST_F(BoardRuntimeTest, TheSdCardIsAFolderOfTheOutputDirectory) {
  simulation_->run_until(10 * kMillisecond);
  EXPECT_EQ(read_file(test_output_dir("board_runtime") + "/board.sd/note.txt"), "written in setup");
}

TEST_F(BoardRuntimeTest, AFaultStopsTheFramesAndDisablesTheDrivers) {
  simulation_->run_until(150 * kMillisecond);
  EXPECT_TRUE(simulation_->stepper("board", 'A')->enabled());
  simulation_->finish();
  EXPECT_TRUE(board_->in_safe_state());
  ASSERT_EQ(board_->faults().size(), 1u);
  EXPECT_EQ(board_->faults().front().text, "invariant broken: asked over serial");
  EXPECT_FALSE(simulation_->stepper("board", 'A')->enabled());
  // dance_start() ran at 5 ms (after the delay), so frames ran at 5.04 ms … 199.96 ms; the loop
  // pass at 200 ms read "fault" before that instant's frame (it was queued first).
  EXPECT_EQ(board_->stats().frames, 4874u);
  EXPECT_NE(simulation_->summary_text().find("\"first\": \"invariant broken: asked over serial\""), std::string::npos);
}

// Warnings are not faults: each kind is listed with its count in the summary's `warnings` and
// in the run report's lines, the first report's detail with it.
TEST_F(BoardRuntimeTest, EveryWarningIsShownWithItsCount) {
  simulation_->run_until(150 * kMillisecond);
  const SimulationReport report = simulation_->finish();
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_EQ(report.warnings[0], "[board] warning ×3: fixture: overrun (first: warned over serial)");
  const nlohmann::json summary = nlohmann::json::parse(simulation_->summary_text());
  EXPECT_EQ(summary["warnings"], nlohmann::json::parse(R"({"board": {"fixture: overrun": 3}})"));
}

}  // namespace
}  // namespace stepdance::sim::test
