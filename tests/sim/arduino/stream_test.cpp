// Reading Serial (the console of the manual backend): bytes, peeking, parsing and timeouts.
#include <gtest/gtest.h>

#include <string>

#include "arduino_fixture.hpp"

namespace {

using stepdance::arduino_manual::delay_calls;
using stepdance::hal::micros_now;
using stepdance::hal_manual::feed_console;

class StreamTest : public stepdance::test_support::ArduinoFixture {};

TEST_F(StreamTest, ReadsAndPeeksFedBytesInOrder) {
  feed_console("ab");
  EXPECT_EQ(Serial.available(), 2);
  EXPECT_EQ(Serial.peek(), 'a');
  EXPECT_EQ(Serial.peek(), 'a');  // peeking twice consumes nothing
  EXPECT_EQ(Serial.available(), 2);
  EXPECT_EQ(Serial.read(), 'a');
  EXPECT_EQ(Serial.read(), 'b');
  EXPECT_EQ(Serial.read(), -1);
  EXPECT_EQ(Serial.peek(), -1);
  EXPECT_EQ(Serial.available(), 0);
  EXPECT_EQ(delay_calls(), 0u);  // plain reads never wait
}

TEST_F(StreamTest, BytesAbove127ReadAsUnsigned) {
  feed_console(std::string("\xFF\x80", 2));
  EXPECT_EQ(Serial.read(), 255);
  EXPECT_EQ(Serial.read(), 128);
}

TEST_F(StreamTest, ReadStringUntilStopsAtAndConsumesTheTerminator) {
  feed_console("G1 X10\nrest");
  EXPECT_EQ(Serial.readStringUntil('\n'), "G1 X10");
  EXPECT_EQ(Serial.available(), 4);
  EXPECT_EQ(delay_calls(), 0u);
}

TEST_F(StreamTest, ParseIntSkipsJunkAndStopsAtTheFirstNonDigit) {
  feed_console("  x-123;45\n");
  EXPECT_EQ(Serial.parseInt(), -123);
  EXPECT_EQ(Serial.read(), ';');
  EXPECT_EQ(Serial.parseInt(), 45);
  EXPECT_EQ(Serial.read(), '\n');
}

TEST_F(StreamTest, ParseFloatReadsAFraction) {
  feed_console("speed 3.25\n-0.5\n.75\n");
  EXPECT_FLOAT_EQ(Serial.parseFloat(), 3.25f);
  EXPECT_FLOAT_EQ(Serial.parseFloat(), -0.5f);
  EXPECT_FLOAT_EQ(Serial.parseFloat(), 0.75f);
}

TEST_F(StreamTest, ReadStringWaitsOneTimeoutAfterTheLastByte) {
  // The wait after "abc": 5 steps of 1 ms of board time, then the 5 ms timeout has passed.
  Serial.setTimeout(5);
  feed_console("abc");
  EXPECT_EQ(Serial.readString(), "abc");
  EXPECT_EQ(delay_calls(), 5u);
  EXPECT_EQ(micros_now(), 5000u);
}

TEST_F(StreamTest, ParseIntGivesZeroWhenNothingArrives) {
  Serial.setTimeout(3);
  EXPECT_EQ(Serial.parseInt(), 0);
  EXPECT_EQ(micros_now(), 3000u);
}

// Bytes that arrive while a read waits are found: the frame timer keeps running during the wait.
uint32_t frames_seen = 0;
void feed_after_two_milliseconds() {
  if (++frames_seen == 50) feed_console("7\n");
}

TEST_F(StreamTest, ByteArrivingDuringTheWaitIsRead) {
  frames_seen = 0;
  stepdance::hal::frame_timer_start(40, &feed_after_two_milliseconds);
  EXPECT_EQ(Serial.parseInt(), 7);
  // Two 1 ms waits (25 frames each): the byte came with frame 50, at 2000 µs.
  EXPECT_EQ(frames_seen, 50u);
  EXPECT_EQ(micros_now(), 2000u);
  EXPECT_EQ(Serial.read(), '\n');
}

TEST_F(StreamTest, FindReadsUpToAndThroughTheTarget) {
  feed_console("xxOOK!ababc?");
  EXPECT_TRUE(Serial.find("OK"));
  EXPECT_EQ(Serial.read(), '!');
  EXPECT_TRUE(Serial.find("abc"));  // a partial match "ab" restarts correctly
  EXPECT_EQ(Serial.read(), '?');
  Serial.setTimeout(2);
  feed_console("nothing here");
  EXPECT_FALSE(Serial.find("zz"));
  EXPECT_EQ(Serial.available(), 0);
}

TEST_F(StreamTest, ReadBytesStopsAtTheLengthOrTheTerminator) {
  feed_console("abcdef12,34");
  char buffer[10] = {};
  EXPECT_EQ(Serial.readBytes(buffer, 4), 4u);
  EXPECT_EQ(std::string(buffer, 4), "abcd");
  EXPECT_EQ(Serial.readBytesUntil(',', buffer, sizeof buffer), 4u);
  EXPECT_EQ(std::string(buffer, 4), "ef12");
  EXPECT_EQ(Serial.read(), '3');
}

TEST_F(StreamTest, TimeoutDefaultsToOneSecondAndResets) {
  EXPECT_EQ(Serial.getTimeout(), 1000u);
  Serial.setTimeout(20);
  EXPECT_EQ(Serial.getTimeout(), 20u);
  stepdance::arduino::reset_state();
  EXPECT_EQ(Serial.getTimeout(), 1000u);
}

}  // namespace
