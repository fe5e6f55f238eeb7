// Recorders on their own: the VCD taps only the input ports it records, and close() lists the
// files it wrote.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "assembly/recorders.hpp"

namespace stepdance::sim {
namespace {

std::string vcd_path(const std::string& name) {
  const std::string folder = STEPDANCE_BUILD_DIR "/test-output/recorders";
  std::filesystem::create_directories(folder);
  return folder + "/" + name + "." + std::to_string(::getpid()) + ".vcd";
}

TEST(RecordersVcdTaps, OnlyARecordedInputPortHasATap) {
  Scheduler scheduler;
  const SimulationOptions options;
  BoardSet boards(scheduler, options, nullptr);
  Recorders recorders(scheduler);
  const std::string path = vcd_path("taps");
  recorders.build_vcd(path, {{"receiver", false, 'B'}}, kMillisecond, boards);
  EXPECT_TRUE(static_cast<bool>(recorders.input_tap("receiver", 'B')));
  EXPECT_FALSE(static_cast<bool>(recorders.input_tap("receiver", 'A')));
  EXPECT_FALSE(static_cast<bool>(recorders.input_tap("sender", 'B')));
  std::vector<std::string> files;
  recorders.close(kMillisecond, files);
  EXPECT_EQ(files, (std::vector<std::string>{path}));
  EXPECT_TRUE(std::filesystem::exists(path));
  std::filesystem::remove(path);
}

TEST(RecordersVcdTaps, WithoutAVcdThereIsNoTapAndNothingIsWritten) {
  Scheduler scheduler;
  const SimulationOptions options;
  BoardSet boards(scheduler, options, nullptr);
  Recorders recorders(scheduler);
  recorders.build_vcd("", {{"receiver", false, 'B'}}, kMillisecond, boards);
  EXPECT_FALSE(static_cast<bool>(recorders.input_tap("receiver", 'B')));
  std::vector<std::string> files;
  recorders.close(kMillisecond, files);
  EXPECT_TRUE(files.empty());
}

}  // namespace
}  // namespace stepdance::sim
