// A board's card against a runaway sketch: it holds at most 64 MiB written per run and 16 open
// files, refusing the rest with kFull, counting it, and keeping what it took.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "board/host/board_storage.hpp"

namespace stepdance::sim {
namespace {

namespace fs = std::filesystem;

std::string fresh_folder(const std::string& name) {
  const std::string folder = STEPDANCE_BUILD_DIR "/test-output/board_storage_" + name;
  fs::remove_all(folder);
  return folder;
}

TEST(BoardStorageLimits, TheCardTakes64MiBAndRefusesTheNextWriteWhole) {
  const std::string folder = fresh_folder("full");
  BoardStorage card(folder);
  int handle = -1;
  ASSERT_EQ(card.open("log.bin", 1, handle), Status::kOk);
  const std::vector<uint8_t> mebibyte(1 << 20, 0x5a);
  for (int i = 0; i < 64; ++i) ASSERT_EQ(card.write(handle, mebibyte.data(), mebibyte.size()), Status::kOk) << i;
  // 64 × 1,048,576 = 67,108,864 bytes: the card is full; one more byte is refused.
  EXPECT_EQ(card.write(handle, mebibyte.data(), 1), Status::kFull);
  EXPECT_EQ(card.write(handle, mebibyte.data(), mebibyte.size()), Status::kFull);
  EXPECT_EQ(card.close(handle), Status::kOk);
  EXPECT_EQ(fs::file_size(folder + "/log.bin"), 67108864u);
  EXPECT_EQ(card.written_bytes(), 67108864u);
  EXPECT_EQ(card.refused_writes(), 2u);
  EXPECT_EQ(card.refused_write_bytes(), 1u + 1048576u);
  // Other files on the same card are refused too: the limit is the card's, not a file's.
  ASSERT_EQ(card.open("other.bin", 1, handle), Status::kOk);
  EXPECT_EQ(card.write(handle, mebibyte.data(), 1), Status::kFull);
}

TEST(BoardStorageLimits, AWriteThatFitsExactlyIsTaken) {
  BoardStorage card(fresh_folder("exact"));
  int handle = -1;
  ASSERT_EQ(card.open("a.bin", 1, handle), Status::kOk);
  const std::vector<uint8_t> most(BoardStorage::kWriteLimitBytes - 10, 1);
  ASSERT_EQ(card.write(handle, most.data(), most.size()), Status::kOk);
  EXPECT_EQ(card.write(handle, most.data(), 11), Status::kFull);
  EXPECT_EQ(card.write(handle, most.data(), 10), Status::kOk);
  EXPECT_EQ(card.refused_writes(), 1u);
}

TEST(BoardStorageLimits, SixteenFilesOpenAtOnceAndAClosedOneMakesRoom) {
  const std::string folder = fresh_folder("open");
  BoardStorage card(folder);
  std::vector<int> handles;
  for (int i = 0; i < 16; ++i) {
    int handle = -1;
    ASSERT_EQ(card.open(("f" + std::to_string(i)).c_str(), 1, handle), Status::kOk) << i;
    handles.push_back(handle);
  }
  int handle = -1;
  EXPECT_EQ(card.open("f16", 1, handle), Status::kFull);
  EXPECT_EQ(card.open("f0", 0, handle), Status::kFull);  // reading counts as well
  EXPECT_EQ(card.refused_opens(), 2u);
  EXPECT_FALSE(fs::exists(folder + "/f16"));
  ASSERT_EQ(card.close(handles[3]), Status::kOk);
  EXPECT_EQ(card.open("f16", 1, handle), Status::kOk);
}

}  // namespace
}  // namespace stepdance::sim
