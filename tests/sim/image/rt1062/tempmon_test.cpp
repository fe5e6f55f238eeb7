// TEMPMON and the OCOTP calibration fuse as Teensyduino's tempmon.c uses them.
#include "image/rt1062/tempmon.hpp"

#include <gtest/gtest.h>

#include "image/chip/peripheral_bus.hpp"
#include "image/rt1062/ocotp.hpp"

namespace stepdance::sim::image::rt1062 {
namespace {

constexpr uint32_t kSense0 = 0x400D8180u, kSense1 = 0x400D8190u, kSense2 = 0x400D8290u, kAna1 = 0x401F44E0u;

class TempChip : public ::testing::Test {
 protected:
  TempChip() : tempmon(Ocotp::kAna1) {
    window.add(tempmon);
    bus.add(window);
    bus.add(ocotp);
  }
  uint32_t rd(uint32_t address) {
    uint32_t value = 0;
    BusRefusal refusal;
    EXPECT_TRUE(bus.read(address, 4, value, refusal)) << refusal.describe();
    return value;
  }
  void wr(uint32_t address, uint32_t value) {
    BusRefusal refusal;
    EXPECT_TRUE(bus.write(address, 4, value, refusal)) << refusal.describe();
  }
  Tempmon tempmon;
  Ocotp ocotp;
  AnalogWindow window;
  PeripheralBus bus;
};

TEST_F(TempChip, ResetValuesAndWindowOffsets) {
  EXPECT_EQ(rd(kSense0), 0x1u);  // POWER_DOWN (RM §16.5.1)
  EXPECT_EQ(rd(kSense1), 0x1u);  // MEASURE_FREQ 1 (RM §16.5.2)
  EXPECT_EQ(rd(kSense2), 0x0u);
  uint32_t value = 0;
  BusRefusal refusal;
  EXPECT_FALSE(bus.read(0x400D81A0u, 4, value, refusal));  // USB_ANALOG's offset: not TEMPMON's
}

TEST_F(TempChip, TempmonInitThenGetTempReadsTwentyFiveDegrees) {
  // tempmon_init (1.59): power on, frequency 3, alarm values from the fuse, start.
  wr(kSense0, rd(kSense0) & ~1u);
  wr(kSense1, 3);
  const uint32_t fuse = rd(kAna1);
  const double hot_temp = fuse & 0xFFu, hot_count = (fuse >> 8) & 0xFFFu, room_count = fuse >> 20;
  const double per_degree = (room_count - hot_count) / (hot_temp - 25.0);
  const auto code = [&](double celsius) {
    return static_cast<uint32_t>(hot_count + (hot_temp - celsius) * per_degree);
  };
  wr(kSense0, rd(kSense0) | (code(85) << 20));
  wr(kSense2, rd(kSense2) | (code(90) << 16));
  wr(kSense2, rd(kSense2) | code(25));
  wr(kSense0, rd(kSense0) | 2u);
  // tempmonGetTemp: wait FINISHED, TEMP_CNT → °C with the fuse's two points.
  const uint32_t sense0 = rd(kSense0);
  ASSERT_TRUE(sense0 & 4u);
  const double count = (sense0 >> 8) & 0xFFFu;
  EXPECT_DOUBLE_EQ(hot_temp - (count - hot_count) * (hot_temp - 25.0) / (room_count - hot_count), 25.0);
  EXPECT_EQ(sense0 >> 20, code(85));
  EXPECT_EQ(rd(kSense2), (code(90) << 16) | code(25));
  wr(kSense0 + 8, 2u);  // CLR MEASURE_TEMP: stops
  EXPECT_EQ(rd(kSense0) & 4u, 0u);
}

TEST_F(TempChip, FuseShadowsReadTheirFusesOthersAreRefused) {
  EXPECT_EQ(rd(kAna1), Ocotp::kAna1);
  wr(kAna1, 0);  // a shadow ignores writes
  EXPECT_EQ(rd(kAna1), Ocotp::kAna1);
  EXPECT_EQ(rd(0x401F4620u) & 0xFFFFFFu, 0x123456u);  // MAC0 (usb_init_serialnumber)
  uint32_t value = 0;
  BusRefusal refusal;
  EXPECT_FALSE(bus.read(0x401F4000u, 4, value, refusal));  // HW_OCOTP_CTRL: fuse reads not modelled
}

}  // namespace
}  // namespace stepdance::sim::image::rt1062
