// A real sketch compiled into a board library and run on a SimBoard: timers, encoders, ports, pins.
#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "board/host/sim_board.hpp"
#include "board/loader/board_library.hpp"
#include "board/loader/sketch_builder.hpp"
#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim {
namespace {

const std::string kStepASketch = STEPDANCE_SOURCE_DIR "/examples/StepASketch/StepASketch.ino";
const std::string kCache = STEPDANCE_BUILD_DIR "/sketch-cache";

std::unique_ptr<SimBoard> load_board(Scheduler& scheduler, const std::string& sketch, const std::string& name,
                                     BoardOptions options = {}) {
  const SketchBuild build = SketchBuilder(kCache).build(sketch);
  EXPECT_TRUE(build.ok) << build.error;
  std::string error;
  auto library = BoardLibrary::load(build.library_path, error);
  EXPECT_NE(library, nullptr) << error;
  options.name = name;
  auto board = std::make_unique<SimBoard>(scheduler, options, std::move(library));
  EXPECT_TRUE(board->attach(error)) << error;
  return board;
}

TEST(SimBoardTest, StepASketchTurnsKnobCountsIntoMotorPulses) {
  Scheduler scheduler;
  auto board = load_board(scheduler, kStepASketch, "driver");
  EXPECT_STREQ(board->definition().name, "Driver Module v1.0");
  board->wire(terminal::Encoder{0}, [](SimTime time) { return time >= 10 * kMillisecond ? int64_t{100} : int64_t{0}; });
  board->power_on(0);
  scheduler.run_until(100 * kMillisecond);
  // +100 counts on the inverted 0.01 mm/count knob: x = −1 mm, a = b = −80 steps, inverted twice.
  EXPECT_EQ(board->ports().sent(0)[SIGNAL_E].forward, 80u);
  EXPECT_EQ(board->ports().sent(0)[SIGNAL_E].reverse, 0u);
  EXPECT_EQ(board->ports().sent(1)[SIGNAL_E].forward, 80u);
  const StepdanceBoardStatsV1 stats = board->stats();
  EXPECT_EQ(board->port_counter("OutputPort", 0, "sent_e_forward"), 80u);  // the board's own count agrees with the wire
  EXPECT_EQ(stats.frames, 2500u);                                          // frames at 40 µs … 100 ms
  EXPECT_FALSE(board->pin_level(14));                                      // ENABLE A driven low: driver on
}

// BoardOptions::encoder_sample_phase_ns: reads see the counts of the last instant phase + k × 40 µs
// (the Teensy backend's sample clock), from the first such instant after the first frame tick on.
TEST(SimBoardTest, WithASamplePhaseEncoderReadsSeeTheLastSampleInstant) {
  Scheduler scheduler;
  BoardOptions options;
  options.frame_phase_ns = 5 * kMicrosecond;
  options.encoder_sample_phase_ns = 3 * kMicrosecond + 123;  // 2 µs minus a little before each tick
  auto board = load_board(scheduler, kStepASketch, "driver", options);
  std::vector<SimTime> asked;
  board->wire(terminal::Encoder{0}, [&asked](SimTime time) {
    asked.push_back(time);
    return int64_t{0};
  });
  board->power_on(0);
  scheduler.run_until(2 * kMillisecond);
  ASSERT_GT(asked.size(), 40u);
  size_t sampled = 0;
  for (const SimTime time : asked) {
    if (time % (40 * kMicrosecond) == 3 * kMicrosecond + 123) {
      ++sampled;
      EXPECT_GT(time, 5 * kMicrosecond) << "no sample before the first tick (at 5 µs) counts";
    } else {
      EXPECT_LE(time, 43 * kMicrosecond + 123) << "read live only until the first sample";
    }
  }
  EXPECT_GT(sampled, 40u) << "the frames' reads, one a frame at least";
}

TEST(SimBoardTest, TwoBoardsRunningOneSketchKeepSeparateGlobals) {
  Scheduler scheduler;
  auto first = load_board(scheduler, kStepASketch, "first");
  auto second = load_board(scheduler, kStepASketch, "second");
  first->wire(terminal::Encoder{0}, [](SimTime time) { return time > kMillisecond ? int64_t{50} : int64_t{0}; });
  second->wire(terminal::Encoder{0}, [](SimTime time) { return time > kMillisecond ? int64_t{-25} : int64_t{0}; });
  first->power_on(0);
  second->power_on(0);
  scheduler.run_until(20 * kMillisecond);
  EXPECT_EQ(first->ports().sent(0)[SIGNAL_E].forward, 40u);
  EXPECT_EQ(second->ports().sent(0)[SIGNAL_E].reverse, 20u);
  EXPECT_EQ(first->port_counter("OutputPort", 0, "sent_e_forward"), 40u);
  EXPECT_EQ(second->port_counter("OutputPort", 0, "sent_e_reverse"), 20u);
}

TEST(SimBoardTest, ConsoleLinesReachTheListener) {
  Scheduler scheduler;
  auto board = load_board(scheduler, kStepASketch, "driver");
  std::vector<std::string> lines;
  board->console().on_line([&lines](const std::string& line) { lines.push_back(line); });
  board->power_on(0);
  scheduler.run_until(2500 * kMillisecond);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].rfind("CPU peak load: ", 0), 0u) << lines[0];
}

TEST(SketchBuilderTest, ACompileErrorNamesTheSketch) {
  const std::string broken = STEPDANCE_BUILD_DIR "/broken_sketch_test.ino";
  { std::ofstream(broken) << "void setup() { undefined_call(); }\nvoid loop() {}\n"; }
  const SketchBuild build = SketchBuilder(kCache).build(broken);
  EXPECT_FALSE(build.ok);
  EXPECT_NE(build.error.find("broken_sketch_test.ino:1:"), std::string::npos) << build.error;
}

}  // namespace
}  // namespace stepdance::sim
