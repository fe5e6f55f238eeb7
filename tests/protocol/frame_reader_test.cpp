// Tests for reading pulses back out of frame words (hand-computed words and expectations).
#include <gtest/gtest.h>

#include "stepdance/protocol/frame_reader.hpp"

namespace stepdance::protocol {
namespace {

TEST(FrameReader, EmptyFrameHasNoPulses) {
  WirePulse pulses[16];
  EXPECT_EQ(read_wire_pulses(FrameWords{}, pulses, 16), 0u);
}

TEST(FrameReader, ForwardXThenReverseY) {
  // X forward: STEP bits 2..3, DIR bits 1..4. Y reverse: STEP bits 6..8, DIR low.
  FrameWords words;
  words.step_bits = 0x0000000Cu | 0x000001C0u;
  words.dir_bits = 0x0000001Eu;
  WirePulse pulses[16];
  ASSERT_EQ(read_wire_pulses(words, pulses, 16), 2u);
  EXPECT_EQ(pulses[0].rise_us, 2);
  EXPECT_EQ(pulses[0].fall_us, 4);
  EXPECT_TRUE(pulses[0].dir_at_rise);
  EXPECT_TRUE(pulses[0].dir_at_fall);
  EXPECT_EQ(pulses[1].rise_us, 6);
  EXPECT_EQ(pulses[1].fall_us, 9);
  EXPECT_FALSE(pulses[1].dir_at_rise);
  EXPECT_FALSE(pulses[1].dir_at_fall);
}

TEST(FrameReader, PulseHighAtLastBitEndsAtThirtyTwo) {
  FrameWords words;
  words.step_bits = 0xC0000000u;  // bits 30..31
  WirePulse pulses[16];
  ASSERT_EQ(read_wire_pulses(words, pulses, 16), 1u);
  EXPECT_EQ(pulses[0].rise_us, 30);
  EXPECT_EQ(pulses[0].fall_us, 32);
}

TEST(FrameReader, StopsAtCapacity) {
  FrameWords words;
  words.step_bits = 0x0000000Cu | 0x000001C0u;
  WirePulse pulses[1];
  EXPECT_EQ(read_wire_pulses(words, pulses, 1), 1u);
}

TEST(FrameReader, CaptureUsesClockAndWrapsCounter) {
  WirePulse pulse;
  pulse.rise_us = 24;
  pulse.fall_us = 31;
  pulse.dir_at_rise = true;
  pulse.dir_at_fall = false;
  const CaptureClock clock{150, 0xFFFFu};
  const CapturedPulse captured = capture_wire_pulse(pulse, clock, 65000, DirSampleEdge::kFalling);
  EXPECT_EQ(captured.rise_ticks, (65000u + 24u * 150u) & 0xFFFFu);  // 68600 - 65536 = 3064
  EXPECT_EQ(captured.rise_ticks, 3064u);
  EXPECT_EQ(captured.fall_ticks, 4114u);  // 65000 + 4650 - 65536
  EXPECT_FALSE(captured.dir_high);
  EXPECT_TRUE(capture_wire_pulse(pulse, clock, 0, DirSampleEdge::kRising).dir_high);
  EXPECT_EQ(rounded_width_us(captured, clock), 7);
}

}  // namespace
}  // namespace stepdance::protocol
