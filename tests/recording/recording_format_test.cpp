// Unit tests of the recording file formats: the original's frame byte, our header, the length file.
#include <gtest/gtest.h>

#include <string.h>

#include "stepdance/recording/recording_format.hpp"

namespace stepdance::recording {
namespace {

TEST(RecordingFormat, OriginalFrameBitsAreTwoPerTrackStepBitHighDirectionLow) {
  // Track 1 forward (11), track 2 reverse (10), track 3 none (00), track 4 forward (11), from
  // bit 0 upwards: 11 | 10 << 2 | 00 << 4 | 11 << 6 = 0x03 + 0x08 + 0xC0.
  const int8_t steps[kTracks] = {1, -1, 0, 1};
  EXPECT_EQ(pack_original_frame(steps), 0xCB);
  int8_t back[kTracks] = {};
  unpack_original_frame(0xCB, back);
  EXPECT_EQ(back[0], 1);
  EXPECT_EQ(back[1], -1);
  EXPECT_EQ(back[2], 0);
  EXPECT_EQ(back[3], 1);
}

TEST(RecordingFormat, TheUnusedCodeZeroOneReadsAsNoStep) {
  int8_t back[kTracks] = {9, 9, 9, 9};
  unpack_original_frame(0x55, back);  // 01 01 01 01
  for (int8_t step : back) EXPECT_EQ(step, 0);
}

TEST(RecordingFormat, HeaderRoundTripsAndIsTellableFromOriginalData) {
  RecordingHeader header;
  header.resolution[0] = 0.01;
  header.resolution[1] = 0.0125;
  header.resolution[2] = 1.0 / 3.0;
  header.resolution[3] = 2.5;
  uint8_t bytes[kHeaderBytes];
  write_header(header, bytes);
  EXPECT_EQ(memcmp(bytes, "SDRECORD", 8), 0);
  EXPECT_EQ(bytes[8], 1);    // version, little-endian
  EXPECT_EQ(bytes[10], 64);  // header length
  // 40 000 ns = 0x00009C40, little-endian.
  EXPECT_EQ(bytes[12], 0x40);
  EXPECT_EQ(bytes[13], 0x9C);
  EXPECT_EQ(bytes[14], 0);
  // 2.5 = 0x4004000000000000: its top byte is the last of the fourth double.
  EXPECT_EQ(bytes[24 + 3 * 8 + 7], 0x40);
  EXPECT_EQ(bytes[24 + 3 * 8 + 6], 0x04);
  RecordingHeader back;
  ASSERT_EQ(read_header(bytes, sizeof(bytes), back), HeaderCheck::kOk);
  for (size_t track = 0; track < kTracks; ++track) EXPECT_EQ(back.resolution[track], header.resolution[track]);

  const uint8_t original_data[16] = {0x03, 0xCB};
  EXPECT_EQ(read_header(original_data, sizeof(original_data), back), HeaderCheck::kNotOurs);
  EXPECT_EQ(read_header(bytes, 40, back), HeaderCheck::kTruncated);
  bytes[8] = 2;
  EXPECT_EQ(read_header(bytes, sizeof(bytes), back), HeaderCheck::kUnsupported);
}

TEST(RecordingFormat, HeaderAcceptsEverySupportedFramePeriodAndNoOther) {
  for (uint32_t period_ns = 0; period_ns <= 50000; period_ns += 500) {
    RecordingHeader header;
    header.frame_period_ns = period_ns;
    uint8_t bytes[kHeaderBytes];
    write_header(header, bytes);
    RecordingHeader back;
    const bool supported = period_ns == 10000 || period_ns == 20000 || period_ns == 25000 || period_ns == 40000;
    EXPECT_EQ(read_header(bytes, sizeof(bytes), back), supported ? HeaderCheck::kOk : HeaderCheck::kUnsupported)
        << period_ns;
    if (supported) {
      EXPECT_EQ(back.frame_period_ns, period_ns);
    }
  }
}

TEST(RecordingFormat, LengthFileIsDecimalWithCrLfAndReadsBack) {
  char text[kLengthTextBytes];
  EXPECT_EQ(format_length(60000000, text), 10u);
  EXPECT_STREQ(text, "60000000\r\n");
  EXPECT_EQ(format_length(UINT64_MAX, text), 22u);
  EXPECT_STREQ(text, "18446744073709551615\r\n");
  uint64_t frames = 0;
  ASSERT_TRUE(parse_length("12345\r\n", 7, frames));
  EXPECT_EQ(frames, 12345u);
  ASSERT_TRUE(parse_length("7", 1, frames));
  EXPECT_EQ(frames, 7u);
  EXPECT_FALSE(parse_length("", 0, frames));
  EXPECT_FALSE(parse_length("12a\r\n", 5, frames));
  EXPECT_FALSE(parse_length("18446744073709551616", 20, frames));  // 2^64
}

TEST(RecordingFormat, FortyMinutesIsSixtyMillionFramesWithoutOverflow) {
  // 40 min × 60 s × 25 000 frames/s. The original computed minutes × 60 × 1 000 000 µs in a
  // 32-bit long: 2.4e9 > 2^31 − 1 already at 36 minutes.
  EXPECT_EQ(frames_for_minutes(40), 60000000u);
  EXPECT_EQ(frames_for_minutes(40) * bytes_per_frame(RecordingFormat::kOriginal), 60000000u);
  EXPECT_EQ(frames_for_minutes(40) * bytes_per_frame(RecordingFormat::kStepdance), 240000000u);
  // A day in our format is 8.64 GB: beyond 32 bits, still exact.
  EXPECT_EQ(frames_for_minutes(24 * 60) * bytes_per_frame(RecordingFormat::kStepdance), 8640000000ull);
}

}  // namespace
}  // namespace stepdance::recording
