// Teensyduino extras on a simulated board: SD.h over the board's storage folder, IntervalTimer.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "board/host/sim_board.hpp"
#include "board/loader/board_library.hpp"
#include "board/loader/sketch_builder.hpp"
#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> run_fixture(const std::string& storage_dir, SimTime until) {
  const SketchBuild build = SketchBuilder(STEPDANCE_BUILD_DIR "/sketch-cache")
                                .build(STEPDANCE_SOURCE_DIR "/tests/sim/assembly/fixtures/TeensyExtras");
  EXPECT_TRUE(build.ok) << build.error;
  if (!build.ok) return {};
  std::string error;
  auto library = BoardLibrary::load(build.library_path, error);
  EXPECT_NE(library, nullptr) << error;
  Scheduler scheduler;
  BoardOptions options;
  options.storage_dir = storage_dir;
  SimBoard board(scheduler, options, std::move(library));
  EXPECT_TRUE(board.attach(error)) << error;
  std::vector<std::string> lines;
  board.console().on_line([&lines](const std::string& line) { lines.push_back(line); });
  board.power_on(0);
  scheduler.run_until(until);
  return lines;
}

TEST(TeensyExtras, SdFilesLandInTheStorageFolderAndIntervalTimerKeepsTime) {
  const fs::path card = fs::path(STEPDANCE_BUILD_DIR) / "teensy-extras-test.sd";
  fs::remove_all(card);
  const std::vector<std::string> lines = run_fixture(card.string(), 150 * kMillisecond);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], "read 6.2832 3.1416");  // 2π and π, 4 digits, through the card
  std::ifstream file(card / "turn.txt");
  std::string content;
  std::getline(file, content);
  EXPECT_EQ(content, "6.2832 3.1416");
  unsigned long ticks = 0, elapsed_us = 0;
  int led = -1;
  ASSERT_EQ(std::sscanf(lines[1].c_str(), "ticks %lu after %lu us led %d", &ticks, &elapsed_us, &led), 3) << lines[1];
  // Before dance_start() timers are served at each loop() entry, the moment loop() reads the
  // time: exactly one call per whole millisecond since begin(), each toggling the LED.
  EXPECT_GE(elapsed_us, 100000u);
  EXPECT_EQ(ticks, elapsed_us / 1000);
  EXPECT_EQ(led, static_cast<int>(ticks % 2));
}

TEST(TeensyExtras, WithoutACardSdBeginFails) {
  const std::vector<std::string> lines = run_fixture("", 150 * kMillisecond);
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(lines[0], "no card");
}

}  // namespace
}  // namespace stepdance::sim
