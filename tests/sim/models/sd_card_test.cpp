// The simulated SD card's timing: transfer time from the rate, stalls every so many kB, a
// failure point; and the contact bounce of a machine-driven switch.
#include <gtest/gtest.h>

#include "models/limit_switch.hpp"
#include "models/sd_card.hpp"

namespace stepdance::sim {
namespace {

TEST(SdCardTiming, AnIdealCardIsInstantAndNeverFails) {
  SdCardTiming card;
  const SdCardTiming::Write write = card.write(512);
  EXPECT_EQ(write.duration, 0);
  EXPECT_FALSE(write.fails);
  EXPECT_EQ(card.read(512), 0);
}

TEST(SdCardTiming, TransfersTakeBytesOverTheRate) {
  SdCardSettings settings;
  settings.write_kb_per_s = 10;  // 10 000 bytes/s: 1000 bytes take 0.1 s
  settings.read_kb_per_s = 500;  // 512 bytes take 1.024 ms
  SdCardTiming card(settings);
  EXPECT_EQ(card.write(1000).duration, 100 * kMillisecond);
  EXPECT_EQ(card.read(512), 1024 * kMicrosecond);
}

TEST(SdCardTiming, AStallComesWithTheWriteThatCrossesEachBoundary) {
  SdCardSettings settings;
  settings.stall_every_kb = 16;  // 16 000 bytes: 31 × 512 = 15 872 below, 32 × 512 = 16 384 past it
  settings.stall = 800 * kMillisecond;
  SdCardTiming card(settings);
  for (int write = 1; write <= 31; ++write) ASSERT_EQ(card.write(512).duration, 0) << write;
  EXPECT_EQ(card.write(512).duration, 800 * kMillisecond);
  EXPECT_EQ(card.stalls(), 1u);
}

TEST(SdCardTiming, WritesBeyondTheFailurePointFailAndWriteNothing) {
  SdCardSettings settings;
  settings.fail_after_bytes = 1000;
  SdCardTiming card(settings);
  EXPECT_FALSE(card.write(512).fails);
  EXPECT_TRUE(card.write(512).fails);   // 1024 > 1000
  EXPECT_FALSE(card.write(488).fails);  // exactly 1000
  EXPECT_EQ(card.bytes_written(), 1000u);
}

TEST(SwitchBounce, TheLineSettlesAfterTheBounceTimeAndTogglesBefore) {
  SwitchBounce bounce(1 * kMillisecond, 7);
  EXPECT_FALSE(bounce.level(0, false));
  const SimTime closed_at = 10 * kMillisecond;
  int toggles = 0;
  bool previous = bounce.level(closed_at, true);
  for (SimTime t = closed_at; t < closed_at + kMillisecond; t += 10 * kMicrosecond) {
    const bool now = bounce.level(t, true);
    toggles += now != previous;
    previous = now;
  }
  EXPECT_GT(toggles, 0);  // 20 slots of seeded levels: a settled line would show none
  for (SimTime t = closed_at + kMillisecond; t < closed_at + 5 * kMillisecond; t += 10 * kMicrosecond) {
    ASSERT_TRUE(bounce.level(t, true)) << t;
  }
}

TEST(SwitchBounce, NoBounceTimeMeansACleanLine) {
  SwitchBounce bounce(0, 7);
  EXPECT_FALSE(bounce.level(0, false));
  EXPECT_TRUE(bounce.level(1, true));
  EXPECT_FALSE(bounce.level(2, false));
}

}  // namespace
}  // namespace stepdance::sim
