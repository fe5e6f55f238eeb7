// IntervalTimer on the manual backend: call counts and times against the board clock.
#include <gtest/gtest.h>

#include <vector>

#include "arduino_fixture.hpp"

namespace {

using stepdance::hal_manual::advance_us;
using stepdance::test_support::reset_arduino_board;

class IntervalTimerTest : public stepdance::test_support::ArduinoFixture {};

std::vector<uint32_t> call_times;
void record_call() { call_times.push_back(micros()); }
int other_calls = 0;
void count_other() { ++other_calls; }

TEST_F(IntervalTimerTest, CallsComeOnePeriodApartAtTheFirstFrameAtOrAfterEachDueTime) {
  call_times.clear();
  IntervalTimer timer;
  ASSERT_TRUE(timer.begin(record_call, 100));  // due at 100, 200, 300 … µs
  delay(1);                                    // 25 frames of 40 µs
  // Frames at 40, 80, 120, …: due 100 → 120, 200 → 200, 300 → 320, 400 → 400, …
  EXPECT_EQ(call_times, (std::vector<uint32_t>{120, 200, 320, 400, 520, 600, 720, 800, 920, 1000}));
}

TEST_F(IntervalTimerTest, TheAverageRateIsExactWithAFractionalPeriod) {
  call_times.clear();
  IntervalTimer timer;
  ASSERT_TRUE(timer.begin(record_call, 62.5f));  // 16 calls per millisecond
  delay(100);
  EXPECT_EQ(call_times.size(), 1600u);
}

TEST_F(IntervalTimerTest, EndStopsAndUpdateChangesThePeriodFromTheNextCall) {
  call_times.clear();
  IntervalTimer timer;
  ASSERT_TRUE(timer.begin(record_call, 1000));
  delay(3);
  EXPECT_EQ(call_times.size(), 3u);
  timer.update(500);  // the call due at 4000 keeps its time, then every 500 µs
  delay(2);           // to 5000: calls at 4000, 4500, 5000
  EXPECT_EQ(call_times.size(), 6u);
  EXPECT_EQ(call_times.back(), 5000u);
  timer.end();
  delay(5);
  EXPECT_EQ(call_times.size(), 6u);
}

TEST_F(IntervalTimerTest, AtMostFourRunAndBadArgumentsAreRefused) {
  IntervalTimer timers[5];
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(timers[i].begin(count_other, 1000)) << i;
  EXPECT_FALSE(timers[4].begin(count_other, 1000));  // the Teensy 4 has four PIT channels
  timers[0].end();
  EXPECT_TRUE(timers[4].begin(count_other, 1000));
  IntervalTimer spare;
  timers[1].end();
  EXPECT_FALSE(spare.begin(nullptr, 1000));
  EXPECT_FALSE(spare.begin(count_other, 0.5));
  EXPECT_FALSE(spare.begin(count_other, -3));
  EXPECT_TRUE(spare.begin(count_other, 1));
}

TEST_F(IntervalTimerTest, ALongStallIsCaughtUpAtMostSixtyFourCallsAtATime) {
  other_calls = 0;
  IntervalTimer timer;
  ASSERT_TRUE(timer.begin(count_other, 10));
  advance_us(100000);  // no frames run: 10 000 calls fell due
  stepdance::arduino::run_interval_timers();
  EXPECT_EQ(other_calls, 64);
  other_calls = 0;
  advance_us(5);
  stepdance::arduino::run_interval_timers();  // the backlog was dropped: next due 10 µs after the stall
  EXPECT_EQ(other_calls, 0);
  advance_us(5);
  stepdance::arduino::run_interval_timers();
  EXPECT_EQ(other_calls, 1);
}

TEST_F(IntervalTimerTest, ResetStateStopsEveryTimer) {
  other_calls = 0;
  IntervalTimer timer;
  ASSERT_TRUE(timer.begin(count_other, 100));
  reset_arduino_board();
  delay(1);
  EXPECT_EQ(other_calls, 0);
}

}  // namespace
