// The SD card in the simulator: a recording lands as a file in the run's output folder and plays
// back in a later run; a slow card makes the recorder overrun (counted, warned, recording kept);
// storage touched from the frame fails the run.
#include <string>

#include "simulation_fixture.hpp"

namespace stepdance::sim::test {
namespace {

std::string record_scenario(const std::string& card) {
  return R"(
duration_s = 3
[[board]]
name = "driver"
sketch = "fixtures/Storage/RecordKnob/RecordKnob.ino"
)" + card +
         R"(
[board.sockets]
A = { device = "stepper" }
[[device]]
name = "knob"
type = "encoder"
board = "driver"
connector = "ENC1"
[[at]]
time_s = 0.2
turn = "knob"
counts = 3000
over_s = 1.0
)";
}

const std::string kScenarioFile = source_path("tests/sim/assembly/storage.toml");

uint64_t counter(const Simulation& simulation, const std::string& block, const std::string& name) {
  for (const SimBoard::BlockCounter& entry : simulation.board("driver")->counters()) {
    if (entry.block.rfind(block, 0) == 0 && entry.name == name) return entry.value;
  }
  return 0;
}

// Steps of track 1 in an original-format file: 11 forward, 10 reverse.
long track_1_steps(const std::string& data) {
  long steps = 0;
  for (char byte : data) {
    const int code = static_cast<unsigned char>(byte) & 3;
    steps += code == 3 ? 1 : code == 2 ? -1 : 0;
  }
  return steps;
}

TEST(StorageScenario, ARecordingIsAFileOfTheOutputFolderAndPlaysBackInALaterRun) {
  auto simulation = create(parse(record_scenario(""), kScenarioFile), "storage_record", false);
  ASSERT_NE(simulation, nullptr);
  const SimulationReport report = simulation->finish();
  const std::string folder = test_output_dir("storage_record") + "/driver.sd/";
  const std::string data = read_file(folder + "take.bin");
  // Two seconds at 25 kHz: 50 000 frames (the loop stops it on its first pass at 2 s).
  EXPECT_NEAR(static_cast<double>(data.size()), 50000, 10);
  EXPECT_EQ(read_file(folder + "take_len.bin"), std::to_string(data.size()) + "\r\n");
  EXPECT_EQ(track_1_steps(data), 3000);  // the knob's 3000 counts, one step each
  EXPECT_EQ(counter(*simulation, "FourTrackRecorder", "overruns"), 0u);
  EXPECT_EQ(simulation->board("driver")->storage_calls_in_isr(), 0u);

  // A later run in the same folder plays the file back: the motor makes the same 3000 steps.
  scenario::Scenario play = parse(R"(
duration_s = 3
[[board]]
name = "driver"
sketch = "fixtures/Storage/PlayBack/PlayBack.ino"
[board.sockets]
A = { device = "stepper" }
)",
                                  kScenarioFile);
  SimulationOptions options;
  plug_test_hooks(options);
  options.output_directory = test_output_dir("storage_record");
  options.write_vcd = false;
  SimulationError error;
  auto replay = Simulation::create(play, options, error);
  ASSERT_NE(replay, nullptr) << error.message;
  replay->finish();
  EXPECT_EQ(replay->stepper("driver", 'A')->position_steps(), 3000);
  EXPECT_EQ(replay->board("driver")->console().text().find("cannot play"), std::string::npos);
}

TEST(StorageScenario, ASlowCardMakesTheRecorderOverrunWithACountedWarning) {
  // 10 kB/s is less than the 25 kB/s the original format needs: the 16 KB ring fills.
  auto simulation =
      create(parse(record_scenario("sd_card = { write_kb_per_s = 10 }"), kScenarioFile), "storage_slow", false);
  ASSERT_NE(simulation, nullptr);
  simulation->finish();
  EXPECT_EQ(counter(*simulation, "FourTrackRecorder", "overruns"), 1u);
  const SimBoard& board = *simulation->board("driver");
  EXPECT_NE(board.console().text().find("too slow"), std::string::npos) << board.console().text();
  EXPECT_EQ(board.storage_calls_in_isr(), 0u);
  EXPECT_TRUE(simulation->board("driver")->stats().frames > 70000);  // frames never stopped
  const std::string folder = test_output_dir("storage_slow") + "/driver.sd/";
  const std::string data = read_file(folder + "take.bin");
  EXPECT_EQ(read_file(folder + "take_len.bin"), std::to_string(data.size()) + "\r\n");
  EXPECT_LT(data.size(), 50000u);
}

TEST(StorageScenario, AStallLongerThanTheBufferOverrunsAsWell) {
  // 800 ms stalls every 16 kB: the ring holds 655 ms of the original format.
  auto simulation = create(parse(record_scenario("sd_card = { stall_every_kb = 16, stall_ms = 800 }"), kScenarioFile),
                           "storage_stall", false);
  ASSERT_NE(simulation, nullptr);
  simulation->finish();
  EXPECT_EQ(counter(*simulation, "FourTrackRecorder", "overruns"), 1u);
  EXPECT_GE(simulation->board("driver")->sd_card().stalls(), 1u);
}

TEST(StorageScenario, StorageTouchedFromTheFrameFailsTheRun) {
  auto simulation = create(parse(R"(
duration_s = 0.1
[[board]]
name = "driver"
sketch = "fixtures/Storage/FrameStorage/FrameStorage.ino"
)",
                                 kScenarioFile),
                           "storage_frame", false);
  ASSERT_NE(simulation, nullptr);
  const SimulationReport report = simulation->finish();
  EXPECT_FALSE(report.all_expectations_met());
  ASSERT_FALSE(report.expectations.empty());
  EXPECT_NE(report.expectations.back().message.find("from the frame"), std::string::npos);
  EXPECT_GE(simulation->board("driver")->storage_calls_in_isr(), 1u);
}

TEST(StorageScenario, CardSettingsAreCheckedWhenTheScenarioLoads) {
  const scenario::LoadResult loaded =
      scenario::parse_scenario(record_scenario("sd_card = { write_kb_per_s = -1, speed = 2 }"), kScenarioFile);
  EXPECT_FALSE(loaded.ok());
  EXPECT_NE(loaded.error_text().find("write_kb_per_s"), std::string::npos) << loaded.error_text();
  EXPECT_NE(loaded.error_text().find("speed"), std::string::npos) << loaded.error_text();
}

}  // namespace
}  // namespace stepdance::sim::test
