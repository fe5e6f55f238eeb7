// Boards that load one board library run one set of code pages: what /proc/self/maps shows.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cstdint>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include "board/host/sim_board.hpp"
#include "board/loader/board_library.hpp"
#include "board/loader/sketch_builder.hpp"
#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim {
namespace {

/// The mapping that holds `address`, as the kernel lists it.
struct Mapping {
  std::string permissions;
  uint64_t inode = 0;
  std::string path;  ///< "" for an anonymous mapping
};

Mapping mapping_at(uintptr_t address) {
  std::ifstream maps("/proc/self/maps");
  std::string line;
  while (std::getline(maps, line)) {
    std::istringstream fields(line);
    std::string range, offset, device;
    Mapping mapping;
    fields >> range >> mapping.permissions >> offset >> device >> mapping.inode;
    std::getline(fields >> std::ws, mapping.path);
    const size_t dash = range.find('-');
    const uintptr_t begin = std::stoull(range.substr(0, dash), nullptr, 16);
    const uintptr_t end = std::stoull(range.substr(dash + 1), nullptr, 16);
    if (address >= begin && address < end) return mapping;
  }
  return {};
}

uint64_t inode_of(const std::string& path) {
  struct stat status {};
  return stat(path.c_str(), &status) == 0 ? status.st_ino : 0;
}

std::unique_ptr<BoardLibrary> load(const std::string& path) {
  std::string error;
  auto library = BoardLibrary::load(path, error);
  EXPECT_NE(library, nullptr) << error;
  return library;
}

TEST(SharedCodePages, EveryBoardOfOneLibraryRunsTheOriginalFilesCodePages) {
  const SketchBuild build = SketchBuilder(STEPDANCE_BUILD_DIR "/sketch-cache")
                                .build(STEPDANCE_SOURCE_DIR "/examples/StepASketch/StepASketch.ino");
  ASSERT_TRUE(build.ok) << build.error;
  const uint64_t original_inode = inode_of(build.library_path);
  ASSERT_NE(original_inode, 0u);
  auto first = load(build.library_path);
  auto second = load(build.library_path);
  auto third = load(build.library_path);
  ASSERT_TRUE(first && second && third);
  for (const BoardLibrary* library : {first.get(), second.get(), third.get()}) {
    ASSERT_GT(library->code().count, 0);
    // Every executable byte of every board: the start, the middle and the last byte of each range.
    for (int i = 0; i < library->code().count; ++i) {
      const uintptr_t begin = library->code().begin[i];
      const uintptr_t end = library->code().end[i];
      for (const uintptr_t address : {begin, begin + (end - begin) / 2, end - 1}) {
        const Mapping mapping = mapping_at(address);
        EXPECT_EQ(mapping.inode, original_inode) << mapping.path;
        EXPECT_EQ(mapping.permissions.substr(0, 3), "r-x") << mapping.path;
      }
    }
  }
  // The copies are still distinct libraries: their code lies at other addresses than the first's.
  EXPECT_NE(second->code().begin[0], first->code().begin[0]);
  EXPECT_NE(third->code().begin[0], second->code().begin[0]);
}

TEST(SharedCodePages, BoardsSharingCodeStillKeepTheirOwnGlobalsAndRunAsAlone) {
  // StepASketch's ±0.01 mm/count knob and 80 steps/mm: 50 counts → 40 steps, -25 → 20 steps
  // back; three boards of one library, run together, each as one board alone would.
  const SketchBuild build = SketchBuilder(STEPDANCE_BUILD_DIR "/sketch-cache")
                                .build(STEPDANCE_SOURCE_DIR "/examples/StepASketch/StepASketch.ino");
  ASSERT_TRUE(build.ok) << build.error;
  Scheduler scheduler;
  std::unique_ptr<SimBoard> boards[3];
  const int64_t counts[3] = {50, -25, 100};
  std::string error;
  for (int i = 0; i < 3; ++i) {
    BoardOptions options;
    options.name = "b" + std::to_string(i);
    boards[i] = std::make_unique<SimBoard>(scheduler, options, load(build.library_path));
    ASSERT_TRUE(boards[i]->attach(error)) << error;
    const int64_t count = counts[i];
    boards[i]->wire(terminal::Encoder{0}, [count](SimTime time) { return time > kMillisecond ? count : int64_t{0}; });
    boards[i]->power_on(0);
  }
  scheduler.run_until(50 * kMillisecond);
  EXPECT_EQ(boards[0]->ports().sent(0)[SIGNAL_E].forward, 40u);
  EXPECT_EQ(boards[1]->ports().sent(0)[SIGNAL_E].reverse, 20u);
  EXPECT_EQ(boards[2]->ports().sent(0)[SIGNAL_E].forward, 80u);
  EXPECT_EQ(boards[1]->ports().sent(0)[SIGNAL_E].forward, 0u);
}

}  // namespace
}  // namespace stepdance::sim
