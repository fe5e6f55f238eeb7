// The Teensy backend's own quadrature.cpp (register-model build) on the XBAR1 and ENC models:
// quadrature_begin() routes the pads through XBAR1, and quadrature_read/write see the knob's
// counts as the world reports them.
#include <gtest/gtest.h>

#include "backend_rig.hpp"
#include "stepdance/hal/hal.hpp"
#include "stepdance/platform/teensy/timers.hpp"

#include <vector>

namespace {

namespace hal = stepdance::hal;
using stepdance::Status;

TEST(BackendQuadrature, ReadsTheKnobsCountsFromTheBegin) {
  auto& w = backend_rig::reset();
  w.io.encoders[0] = 1000;  // turned before the sketch began
  w.io.encoders[1] = -3;
  ASSERT_EQ(hal::quadrature_begin(0), Status::kOk);
  ASSERT_EQ(hal::quadrature_begin(1), Status::kOk);
  EXPECT_EQ(hal::quadrature_read(0), 0);
  w.io.encoders[0] = 1012;
  w.io.encoders[1] = -10;
  EXPECT_EQ(hal::quadrature_read(0), 12);
  EXPECT_EQ(hal::quadrature_read(1), -7);
  hal::quadrature_write(1, 100000);
  w.io.encoders[1] = -8;
  EXPECT_EQ(hal::quadrature_read(1), 100002);
  EXPECT_EQ(hal::quadrature_read(0), 12);
}

}  // namespace

namespace {

namespace teensy = stepdance::platform::teensy;

constexpr uint32_t kPitLdval3 = 0x130, kPitTctrl3 = 0x138, kPitTflg3 = 0x13C;  // RM §53.4, channel 3
constexpr uint8_t kPitTrigger3 = 56 + 3;  // XBAR1 input PIT_TRIGGER3 (RM chapter 4)

void no_frame() {}

// The sample clock's expiry as the chip makes it: TIF set, PIT_TRIGGER3 pulsed through XBAR1.
void expire_sample_clock(backend_rig::World& w) {
  w.pit.registers[kPitTflg3] = 1;
  w.blocks->xbar1().pulse(kPitTrigger3);
}

// The LDVAL values written to channel 3, in order.
std::vector<uint32_t> ldval3_writes(const backend_rig::World& w) {
  std::vector<uint32_t> values;
  for (const auto& [offset, value] : w.pit.writes) {
    if (offset == kPitLdval3) values.push_back(value);
  }
  return values;
}

TEST(BackendQuadrature, WhileFramesRunEachReadSeesTheSampleClocksLastInstant) {
  auto& w = backend_rig::reset();
  w.io.encoders[0] = 0;
  ASSERT_EQ(hal::quadrature_begin(0), Status::kOk);
  EXPECT_EQ(w.blocks->xbar1().input_of(70), kPitTrigger3) << "ENC1 TRIGGER (XBAR1 output 70) on PIT_TRIGGER3";
  ASSERT_EQ(hal::frame_timer_start(40, no_frame), Status::kOk);
  // PERCLK here is IPG = 150 MHz (CSCMR1 0): a frame is 6000 ticks, the 2 µs lead 300. The PIT
  // expires every LDVAL + 1 ticks (RM §53.5.1): first period 5700, then 6000.
  EXPECT_EQ(ldval3_writes(w), (std::vector<uint32_t>{5699, 5999}));
  EXPECT_EQ(w.pit.registers[kPitTctrl3], 1u) << "channel 3 enabled, no interrupt";
  w.io.encoders[0] = 40;
  EXPECT_EQ(hal::quadrature_read(0), 40) << "before the first expiry: live";
  w.io.encoders[0] = 100;
  expire_sample_clock(w);
  w.io.encoders[0] = 130;  // turned after the sample
  EXPECT_EQ(hal::quadrature_read(0), 100);
  expire_sample_clock(w);
  EXPECT_EQ(hal::quadrature_read(0), 130);
  hal::quadrature_write(0, 1000);
  w.io.encoders[0] = 150;
  EXPECT_EQ(hal::quadrature_read(0), 1000) << "no sample since the write";
  expire_sample_clock(w);
  EXPECT_EQ(hal::quadrature_read(0), 1020);
  teensy::frame_timer_stop();
  EXPECT_EQ(w.pit.registers[kPitTctrl3], 0u) << "the channel is given back";
  w.io.encoders[0] = 160;
  EXPECT_EQ(hal::quadrature_read(0), 1030) << "stopped: live again, the offset kept";
}

TEST(BackendQuadrature, AChannelASketchHoldsIsLeftAloneAndTheCountsAreReadLive) {
  auto& w = backend_rig::reset();
  w.pit.registers[kPitTctrl3] = 1;  // an IntervalTimer runs on channel 3
  w.pit.registers[kPitLdval3] = 12345;
  w.io.encoders[0] = 0;
  ASSERT_EQ(hal::quadrature_begin(0), Status::kOk);
  ASSERT_EQ(hal::frame_timer_start(40, no_frame), Status::kOk);
  EXPECT_EQ(w.pit.registers[kPitLdval3], 12345u);
  w.io.encoders[0] = 7;
  w.pit.registers[kPitTflg3] = 1;  // the sketch's timer expires: not our sample
  EXPECT_EQ(hal::quadrature_read(0), 7);
  teensy::frame_timer_stop();
  EXPECT_EQ(w.pit.registers[kPitTctrl3], 1u) << "still the sketch's";
}

}  // namespace
