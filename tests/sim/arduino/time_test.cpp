// millis(), micros(), delay() and elapsedMillis/elapsedMicros over the manual backend's clock.
#include <gtest/gtest.h>

#include "arduino_fixture.hpp"

namespace {

using stepdance::arduino_manual::delay_calls;
using stepdance::arduino_manual::delayed_us;
using stepdance::hal_manual::advance_us;
using stepdance::test_support::reset_arduino_board;

class TimeTest : public stepdance::test_support::ArduinoFixture {};

uint32_t frames = 0;
uint32_t khz_ticks = 0;
void count_frame() { ++frames; }
void count_khz_tick() { ++khz_ticks; }

TEST_F(TimeTest, MillisAndMicrosFollowTheBoardClock) {
  reset_arduino_board(1000);
  EXPECT_EQ(micros(), 1000u);
  EXPECT_EQ(millis(), 1u);
  advance_us(2500);
  EXPECT_EQ(micros(), 3500u);
  EXPECT_EQ(millis(), 3u);
}

TEST_F(TimeTest, MillisStaysExactAcrossTheMicrosecondWrap) {
  // Start 1000 µs before micros() wraps: 4 294 966 296 µs = 4 294 966 ms (and 296 µs).
  reset_arduino_board(0xFFFFFFFFu - 999u);
  EXPECT_EQ(micros(), 4294966296u);
  EXPECT_EQ(millis(), 4294966u);
  // 2000 µs later micros() has wrapped to 1000, while millis() keeps counting:
  // 4 294 968 296 µs = 4 294 968 ms.
  advance_us(2000);
  EXPECT_EQ(micros(), 1000u);
  EXPECT_EQ(millis(), 4294968u);
  // Wrap-safe arithmetic on micros() sees the 2000 µs.
  EXPECT_EQ(static_cast<uint32_t>(micros() - 4294966296u), 2000u);
}

TEST_F(TimeTest, DelayLetsFramesAndTheKilohertzTimerRun) {
  frames = 0;
  khz_ticks = 0;
  stepdance::hal::frame_timer_start(40, &count_frame);
  stepdance::hal::khz_timer_start(1000, &count_khz_tick);
  delay(3);
  EXPECT_EQ(micros(), 3000u);
  EXPECT_EQ(frames, 75u);  // 3000 µs / 40 µs
  EXPECT_EQ(khz_ticks, 3u);
  EXPECT_EQ(delay_calls(), 1u);
  EXPECT_EQ(delayed_us(), 3000u);
}

TEST_F(TimeTest, DelayMicrosecondsRunsWholeFramesAndKeepsTheRemainder) {
  frames = 0;
  stepdance::hal::frame_timer_start(40, &count_frame);
  delayMicroseconds(100);  // two frames (80 µs), then 20 µs more
  EXPECT_EQ(micros(), 100u);
  EXPECT_EQ(frames, 2u);
}

TEST_F(TimeTest, DelayZeroDoesNothing) {
  delay(0);
  EXPECT_EQ(micros(), 0u);
  EXPECT_EQ(delay_calls(), 0u);
}

TEST_F(TimeTest, YieldLetsNoTimePass) {
  yield();
  EXPECT_EQ(micros(), 0u);
  EXPECT_EQ(delay_calls(), 0u);
}

TEST_F(TimeTest, ElapsedMillisCountsUpAndRestartsOnAssignment) {
  elapsedMillis since_start;
  advance_us(1500);
  EXPECT_EQ(static_cast<uint32_t>(since_start), 1u);
  since_start = 0;
  advance_us(2000);
  EXPECT_EQ(static_cast<uint32_t>(since_start), 2u);
  since_start += 10;
  EXPECT_EQ(static_cast<uint32_t>(since_start), 12u);
  since_start -= 5;
  EXPECT_EQ(static_cast<uint32_t>(since_start), 7u);
  EXPECT_TRUE(since_start > 6);
}

TEST_F(TimeTest, ElapsedMicrosCountsMicroseconds) {
  elapsedMicros since_start = 40;
  advance_us(250);
  EXPECT_EQ(static_cast<uint32_t>(since_start), 290u);
  since_start = 0;
  delayMicroseconds(15);
  EXPECT_EQ(static_cast<uint32_t>(since_start), 15u);
}

}  // namespace
