// SNVS's RTCs as Teensyduino's startup.c and rtc.c set and read them.
#include "image/rt1062/snvs.hpp"

#include <gtest/gtest.h>

#include "fake_chip.hpp"

namespace stepdance::sim::image::rt1062 {
namespace {

uint32_t rd(Snvs& snvs, uint32_t offset) {
  uint32_t value = 0;
  EXPECT_EQ(snvs.read(offset, 4, value), Access::kOk);
  return value;
}

TEST(Snvs, StartupSetsTheSrtcAndTheHpRtcCountsSecondsFromIt) {
  testing::FakeChip chip;
  Snvs snvs(chip);
  ASSERT_EQ(rd(snvs, 0x38) & 1u, 0u);  // SRTC not running at reset
  // startup.c: SRTC = 2019-01-01 (1546300800 s) in 32.768 kHz ticks, start it, then HPCR RTC_EN | HP_TS.
  snvs.write(0x54, 4, 1546300800u << 15);
  snvs.write(0x50, 4, 1546300800u >> 17);
  snvs.write(0x38, 4, rd(snvs, 0x38) | 1u);
  snvs.write(0x08, 4, rd(snvs, 0x08) | 1u | (1u << 16));
  EXPECT_EQ(rd(snvs, 0x08) & (1u << 16), 0u);  // HP_TS clears itself
  chip.advance_to(3 * kSecond + 500 * kMillisecond);
  // rtc_get(): (MR << 17) | (LR >> 15) = whole seconds.
  EXPECT_EQ((rd(snvs, 0x24) << 17) | (rd(snvs, 0x28) >> 15), 1546300803u);
  EXPECT_EQ(snvs.srtc_count(), (uint64_t{1546300800u} << 15) + 3u * 32768u + 16384u);
  uint32_t value = 0;
  EXPECT_EQ(snvs.read(0x34, 4, value), Access::kUnmodelled);  // LPLR
}

}  // namespace
}  // namespace stepdance::sim::image::rt1062
