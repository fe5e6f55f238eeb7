// Choosing the frame period: the derived rates, refusals on the fault path, formats per period.
#include "stepdance/core/frame_period.hpp"

#include <gtest/gtest.h>

#include "hal_manual.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/core/units.hpp"
#include "stepdance/io/output_port.hpp"
#include "stepdance/motion/channel.hpp"
#include "support/engine_fixture.hpp"

namespace stepdance {
namespace {

class FramePeriodTest : public test_support::EngineFixture {};

TEST_F(FramePeriodTest, DefaultsToFortyMicrosecondsAndTheOriginalNamesFollowTheChoice) {
  EXPECT_EQ(CORE_FRAME_PERIOD_US, 40u);
  EXPECT_EQ(CORE_FRAME_FREQ_HZ, 25000u);
  ASSERT_EQ(set_frame_period_us(10), Status::kOk);
  EXPECT_EQ(CORE_FRAME_PERIOD_US, 10u);
  EXPECT_EQ(CORE_FRAME_FREQ_HZ, 100000u);
  EXPECT_DOUBLE_EQ(CORE_FRAME_PERIOD_S, 10e-6);
  EXPECT_EQ(frames_per_kilohertz_tick(), 100u);
  ASSERT_EQ(set_frame_period_us(20), Status::kOk);
  EXPECT_EQ(CORE_FRAME_FREQ_HZ, 50000u);
  EXPECT_EQ(fault_reason(), FaultReason::kNone);
}

TEST_F(FramePeriodTest, OnlyTenTwentyTwentyFiveAndFortyAreSupported) {
  for (uint32_t period = 0; period <= 1000; ++period) {
    const bool expected = period == 10 || period == 20 || period == 25 || period == 40;
    EXPECT_EQ(frame_period_supported(period), expected) << period;
  }
}

TEST_F(FramePeriodTest, AnUnsupportedPeriodIsRefusedOnTheFaultPathAndTheEngineDoesNotStart) {
  EXPECT_EQ(set_frame_period_us(8), Status::kBadArgument);
  EXPECT_EQ(frame_period_us(), 40u);  // unchanged
  EXPECT_EQ(fault_reason(), FaultReason::kBadConfiguration);
  EXPECT_NE(dance_start(), Status::kOk);
}

TEST_F(FramePeriodTest, ThePeriodCannotChangeWhileTheEngineRuns) {
  ASSERT_EQ(dance_start(), Status::kOk);
  EXPECT_EQ(set_frame_period_us(10), Status::kBusy);
  EXPECT_EQ(frame_period_us(), 40u);
  EXPECT_EQ(fault_reason(), FaultReason::kBadConfiguration);
}

TEST_F(FramePeriodTest, TheFrameClockAndTheKilohertzTickRunAtTheChosenPeriod) {
  ASSERT_EQ(set_frame_period_us(10), Status::kOk);
  ASSERT_EQ(dance_start(), Status::kOk);
  const uint32_t before_us = hal::micros_now();
  hal_manual::run_frames(1000);
  EXPECT_EQ(hal::micros_now() - before_us, 10000u);  // 1000 frames of 10 µs
  EXPECT_EQ(engine().frame_count(), 1000u);
}

// The original's table (original-library.md §2.2): the window of each fixed format, and which
// frame periods it fits (its transmission must end before the frame does).
TEST_F(FramePeriodTest, AFormatLongerThanTheFrameIsRefusedAtBegin) {
  struct Case {
    uint32_t period_us;
    uint8_t format;
    bool accepted;
  };
  const Case cases[] = {
      {40, OUTPUT_FRAME_32US, true},  {40, OUTPUT_FRAME_4US, true},  {25, OUTPUT_FRAME_32US, false},
      {25, OUTPUT_FRAME_16US, true},  {20, OUTPUT_FRAME_16US, true}, {20, OUTPUT_FRAME_32US, false},
      {10, OUTPUT_FRAME_16US, false}, {10, OUTPUT_FRAME_8US, true},  {10, OUTPUT_FRAME_4US, true},
  };
  for (const Case& c : cases) {
    test_support::reset_global_state();
    ASSERT_EQ(set_frame_period_us(c.period_us), Status::kOk);
    OutputPort a;
    const Status begun = a.begin(OUTPUT_A, c.format, OUTPUT_TRANSMIT_ON_FRAME);
    EXPECT_EQ(begun == Status::kOk, c.accepted) << c.period_us << " µs, format " << int(c.format);
    EXPECT_EQ(fault_reason() == FaultReason::kBadConfiguration, !c.accepted);
    EXPECT_EQ(dance_start() == Status::kOk, c.accepted);
  }
}

TEST_F(FramePeriodTest, AFixedFormatIsCheckedAgainAtStartWhenThePeriodChangedAfterBegin) {
  OutputPort a;
  ASSERT_EQ(a.begin(OUTPUT_A, OUTPUT_FRAME_32US, OUTPUT_TRANSMIT_ON_FRAME), Status::kOk);
  ASSERT_EQ(set_frame_period_us(20), Status::kOk);
  EXPECT_NE(dance_start(), Status::kOk);
  EXPECT_EQ(fault_reason(), FaultReason::kBadConfiguration);
}

TEST_F(FramePeriodTest, BeginWithoutAFormatUsesTheWholeFrameOfThePeriodStarted) {
  OutputPort a;
  ASSERT_EQ(a.begin(OUTPUT_A), Status::kOk);
  ASSERT_EQ(set_frame_period_us(10), Status::kOk);
  ASSERT_EQ(dance_start(), Status::kOk);
  EXPECT_EQ(a.layout().window_us, 9u);  // period − 1 µs: the lines rest low for the last µs
  EXPECT_EQ(a.layout().first_pulse_us, 1u);
  // E alone fits: STEP 1..8 µs, DIR 0..9 µs.
  a.add_signal(SIGNAL_E, DIRECTION_FORWARD);
  hal_manual::run_frames(1);
  EXPECT_EQ(hal_manual::last_frame(OUTPUT_A).step_bits, 0b11111110u);
  EXPECT_EQ(hal_manual::last_frame(OUTPUT_A).dir_bits, 0b111111111u);
}

TEST_F(FramePeriodTest, AChannelWhoseSignalCanNeverFitItsPortIsRefusedAtStart) {
  OutputPort a;
  ASSERT_EQ(set_frame_period_us(10), Status::kOk);
  ASSERT_EQ(a.begin(OUTPUT_A, OUTPUT_FRAME_8US, OUTPUT_TRANSMIT_ON_FRAME), Status::kOk);
  Channel z;
  Channel e;
  ASSERT_EQ(z.begin(&a, SIGNAL_Z), Status::kOk);  // Z: 6 µs pulse + DIR margins = 8 µs, fits
  ASSERT_EQ(dance_start(), Status::kOk);
  engine().stop();
  ASSERT_EQ(e.begin(&a, SIGNAL_E), Status::kOk);  // E needs 9 µs
  EXPECT_NE(dance_start(), Status::kOk);
  EXPECT_EQ(fault_reason(), FaultReason::kBadConfiguration);
}

TEST_F(FramePeriodTest, PulsesAPortCanNeverCarryAreRefusedAndCountedNotKeptForever) {
  OutputPort a;
  ASSERT_EQ(set_frame_period_us(10), Status::kOk);
  ASSERT_EQ(a.begin(OUTPUT_A, OUTPUT_FRAME_4US, OUTPUT_TRANSMIT_ON_FRAME), Status::kOk);
  ASSERT_EQ(dance_start(), Status::kOk);
  a.add_signal(SIGNAL_Y, DIRECTION_FORWARD);
  a.add_signal(SIGNAL_X, DIRECTION_FORWARD);
  EXPECT_EQ(a.pending(SIGNAL_Y), 0);
  EXPECT_EQ(a.pulses_refused(), 1u);
  EXPECT_EQ(fault_level(), static_cast<uint8_t>(FaultLevel::kWarning));
  hal_manual::run_frames(1);
  EXPECT_EQ(hal_manual::last_frame(OUTPUT_A).step_bits, 0b110u);  // X at 1..3 µs
  EXPECT_EQ(hal_manual::last_frame(OUTPUT_A).dir_bits, 0b1111u);  // DIR 0..4 µs
}

TEST_F(FramePeriodTest, AChannelSteps100000TimesASecondInTenMicrosecondFrames) {
  ASSERT_EQ(set_frame_period_us(10), Status::kOk);
  OutputPort a;
  Channel x;
  ASSERT_EQ(a.begin(OUTPUT_A), Status::kOk);
  ASSERT_EQ(x.begin(&a, SIGNAL_X), Status::kOk);
  ASSERT_EQ(dance_start(), Status::kOk);
  x.input_target_position.write(1e9, ABSOLUTE);  // far away: one pulse every frame
  hal_manual::run_frames(100000);                // one second of 10 µs frames
  EXPECT_EQ(a.pulses_sent(SIGNAL_X, DIRECTION_FORWARD), 100000u);
  EXPECT_DOUBLE_EQ(x.current_position, 100000.0);
}

}  // namespace
}  // namespace stepdance
