// A real sketch compiled into a board library and run on a SimBoard: timers, encoders, ports, pins.
#include <gtest/gtest.h>

#include <memory>
#include <fstream>
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

std::unique_ptr<SimBoard> load_board(Scheduler& scheduler, const std::string& sketch, const std::string& name) {
  const SketchBuild build = SketchBuilder(kCache).build(sketch);
  EXPECT_TRUE(build.ok) << build.error;
  std::string error;
  auto library = BoardLibrary::load(build.library_path, error);
  EXPECT_NE(library, nullptr) << error;
  BoardOptions options;
  options.name = name;
  auto board = std::make_unique<SimBoard>(scheduler, options, std::move(library));
  EXPECT_TRUE(board->attach(error)) << error;
  return board;
}

TEST(SimBoardTest, StepASketchTurnsKnobCountsIntoMotorPulses) {
  Scheduler scheduler;
  auto board = load_board(scheduler, kStepASketch, "driver");
  EXPECT_STREQ(board->definition().name, "Driver Module v1.0");
  board->connect_encoder(0, [](SimTime time) { return time >= 10 * kMillisecond ? int64_t{100} : int64_t{0}; });
  board->power_on(0);
  scheduler.run_until(100 * kMillisecond);
  // +100 counts on the inverted 0.01 mm/count knob: x = −1 mm, a = b = −80 steps, inverted twice.
  EXPECT_EQ(board->sent(0)[SIGNAL_E].forward, 80u);
  EXPECT_EQ(board->sent(0)[SIGNAL_E].reverse, 0u);
  EXPECT_EQ(board->sent(1)[SIGNAL_E].forward, 80u);
  const StepdanceBoardStatsV1 stats = board->stats();
  EXPECT_EQ(board->port_counter("OutputPort", 0, "sent_e_forward"), 80u);  // the board's own count agrees with the wire
  EXPECT_EQ(stats.frames, 2500u);               // frames at 40 µs … 100 ms
  EXPECT_FALSE(board->pin_level(14));           // ENABLE A driven low: driver on
}

TEST(SimBoardTest, TwoBoardsRunningOneSketchKeepSeparateGlobals) {
  Scheduler scheduler;
  auto first = load_board(scheduler, kStepASketch, "first");
  auto second = load_board(scheduler, kStepASketch, "second");
  first->connect_encoder(0, [](SimTime time) { return time > kMillisecond ? int64_t{50} : int64_t{0}; });
  second->connect_encoder(0, [](SimTime time) { return time > kMillisecond ? int64_t{-25} : int64_t{0}; });
  first->power_on(0);
  second->power_on(0);
  scheduler.run_until(20 * kMillisecond);
  EXPECT_EQ(first->sent(0)[SIGNAL_E].forward, 40u);
  EXPECT_EQ(second->sent(0)[SIGNAL_E].reverse, 20u);
  EXPECT_EQ(first->port_counter("OutputPort", 0, "sent_e_forward"), 40u);
  EXPECT_EQ(second->port_counter("OutputPort", 0, "sent_e_reverse"), 20u);
}

TEST(SimBoardTest, ConsoleLinesReachTheListener) {
  Scheduler scheduler;
  auto board = load_board(scheduler, kStepASketch, "driver");
  std::vector<std::string> lines;
  board->on_console_line([&lines](const std::string& line) { lines.push_back(line); });
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
