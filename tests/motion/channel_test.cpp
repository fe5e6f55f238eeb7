// Unit tests of the Channel stepping law: rate, dead band, reversal, limits, filter, deep push.
#include <gtest/gtest.h>

#include "hal_manual.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/core/engine.hpp"
#include "stepdance/io/output_port.hpp"
#include "stepdance/motion/channel.hpp"
#include "support/engine_fixture.hpp"

namespace stepdance {
namespace {

// One X pulse, read off the protocol by hand: STEP high 2–4 µs (bits 2, 3); a forward DIR is
// high from 1 µs before to 1 µs after it (bits 1..4); a reverse DIR stays low.
constexpr uint32_t kStepBitsX = 0x0000000Cu;
constexpr uint32_t kForwardDirBitsX = 0x0000001Eu;

// Far more steps than any test can emit: the channel sees continuous demand.
constexpr double kFarAway = 1e9;

class ChannelTest : public test_support::EngineFixture {
 protected:
  void SetUp() override {
    EngineFixture::SetUp();
    ASSERT_EQ(port.begin(OUTPUT_A), Status::kOk);
  }

  void start(Channel& channel) {
    ASSERT_EQ(channel.begin(&port, SIGNAL_X), Status::kOk);
    ASSERT_EQ(dance_start(), Status::kOk);
  }

  uint32_t sent_forward() const { return port.pulses_sent(SIGNAL_X, DIRECTION_FORWARD); }
  uint32_t sent_reverse() const { return port.pulses_sent(SIGNAL_X, DIRECTION_REVERSE); }
  uint32_t sent_total() const { return sent_forward() + sent_reverse(); }

  OutputPort port;
};

// ---- Rate limiter ------------------------------------------------------------------------------

class ChannelRateTest : public ChannelTest, public ::testing::WithParamInterface<uint32_t> {};

TEST_P(ChannelRateTest, EmitsExactlyTheRateInAny25000Frames) {
  const uint32_t rate = GetParam();
  Channel channel;
  start(channel);
  channel.set_max_pulse_rate(rate);
  channel.input_target_position.write(kFarAway, ABSOLUTE);

  hal_manual::run_frames(25000);  // the first second of demand
  EXPECT_EQ(sent_forward(), rate);
  EXPECT_EQ(channel.pulses_forward(), rate);

  hal_manual::run_frames(12345);  // a window that starts mid-period
  const uint32_t before = sent_forward();
  hal_manual::run_frames(25000);
  EXPECT_EQ(sent_forward() - before, rate);
  EXPECT_EQ(sent_reverse(), 0u);
}

INSTANTIATE_TEST_SUITE_P(Rates, ChannelRateTest, ::testing::Values(10000u, 25000u, 1u, 7777u));

TEST_F(ChannelTest, IdleTimeDoesNotBankABurst) {
  Channel channel;
  start(channel);
  channel.set_max_pulse_rate(1000);  // one pulse per 25 frames
  hal_manual::run_frames(100000);    // four idle seconds
  EXPECT_EQ(sent_total(), 0u);

  channel.input_target_position.write(kFarAway, ABSOLUTE);
  hal_manual::run_frames(25);
  EXPECT_EQ(sent_forward(), 1u);  // the first pulse goes at once, the second waits its turn
  hal_manual::run_frames(1);
  EXPECT_EQ(sent_forward(), 2u);
  hal_manual::run_frames(25000 - 26);
  EXPECT_EQ(sent_forward(), 1000u);
}

TEST_F(ChannelTest, ZeroRateNeverPulses) {
  Channel channel;
  start(channel);
  channel.set_max_pulse_rate(0);
  channel.input_target_position.write(5.0, ABSOLUTE);
  hal_manual::run_frames(1000);
  EXPECT_EQ(sent_total(), 0u);
  EXPECT_EQ(channel.current_position, 0.0);
}

TEST_F(ChannelTest, AtMostOnePulsePerFrame) {
  Channel channel;
  start(channel);
  channel.input_target_position.write(1000.0, ABSOLUTE);
  for (uint32_t frame = 1; frame <= 200; ++frame) {
    hal_manual::run_frames(1);
    ASSERT_EQ(sent_forward(), frame);
    ASSERT_EQ(port.pending(SIGNAL_X), 0);
  }
  EXPECT_EQ(channel.current_position, 200.0);
}

TEST_F(ChannelTest, ReversalCostsOneFrameAtFullRate) {
  Channel channel;
  start(channel);
  channel.input_target_position.write(3.0, ABSOLUTE);
  hal_manual::run_frames(3);
  EXPECT_EQ(sent_forward(), 3u);
  EXPECT_EQ(channel.current_position, 3.0);

  channel.input_target_position.write(0.0, ABSOLUTE);
  hal_manual::run_frames(1);  // the reversal frame: no pulse
  EXPECT_EQ(sent_reverse(), 0u);
  EXPECT_EQ(hal_manual::last_frame(OUTPUT_A).step_bits, 0u);
  for (uint32_t pulses = 1; pulses <= 3; ++pulses) {
    hal_manual::run_frames(1);
    EXPECT_EQ(sent_reverse(), pulses);
  }
  EXPECT_EQ(channel.current_position, 0.0);
  hal_manual::run_frames(5);
  EXPECT_EQ(sent_total(), 6u);
}

// ---- Dead band and fractional targets -----------------------------------------------------------

TEST_F(ChannelTest, HalfAStepIsInsideTheDeadBand) {
  Channel channel;
  start(channel);
  channel.input_target_position.write(0.5, ABSOLUTE);
  hal_manual::run_frames(5);
  EXPECT_EQ(sent_total(), 0u);

  channel.input_target_position.write(0.5 + 1.0 / 1024, ABSOLUTE);
  hal_manual::run_frames(5);
  EXPECT_EQ(sent_forward(), 1u);
  EXPECT_EQ(channel.current_position, 1.0);  // error now −0.499…: kept, not stepped

  channel.input_target_position.write(-0.5, ABSOLUTE);  // error −1.5: one reverse step to 0
  hal_manual::run_frames(5);
  EXPECT_EQ(sent_reverse(), 1u);
  EXPECT_EQ(channel.current_position, 0.0);
  EXPECT_EQ(channel.target_position, -0.5);
}

// ---- Output direction ---------------------------------------------------------------------------

TEST_F(ChannelTest, InvertingTwiceStaysInverted) {
  Channel channel;
  start(channel);
  channel.invert_output();
  channel.invert_output();  // the original toggled back here; a re-run setup() must not undo it
  channel.input_target_position.write(1.0, ABSOLUTE);
  hal_manual::run_frames(1);
  EXPECT_EQ(hal_manual::last_frame(OUTPUT_A).dir_bits, 0u);  // forward step, DIR low on the wire
  EXPECT_EQ(sent_reverse(), 1u);

  channel.invert_output(false);
  channel.input_target_position.write(2.0, ABSOLUTE);
  hal_manual::run_frames(1);
  EXPECT_EQ(hal_manual::last_frame(OUTPUT_A).dir_bits, kForwardDirBitsX);
}

TEST_F(ChannelTest, InvertFlipsOnlyTheWireDirection) {
  Channel channel;
  start(channel);
  channel.input_target_position.write(1.0, ABSOLUTE);
  hal_manual::run_frames(1);
  EXPECT_EQ(hal_manual::last_frame(OUTPUT_A).step_bits, kStepBitsX);
  EXPECT_EQ(hal_manual::last_frame(OUTPUT_A).dir_bits, kForwardDirBitsX);

  channel.invert_output();
  channel.input_target_position.write(2.0, ABSOLUTE);
  hal_manual::run_frames(1);
  EXPECT_EQ(hal_manual::last_frame(OUTPUT_A).step_bits, kStepBitsX);
  EXPECT_EQ(hal_manual::last_frame(OUTPUT_A).dir_bits, 0u);
  EXPECT_EQ(sent_reverse(), 1u);
  EXPECT_EQ(channel.current_position, 2.0);
  EXPECT_EQ(channel.pulses_forward(), 2u);

  channel.invert_output(false);
  channel.input_target_position.write(3.0, ABSOLUTE);
  hal_manual::run_frames(1);
  EXPECT_EQ(hal_manual::last_frame(OUTPUT_A).dir_bits, kForwardDirBitsX);
  EXPECT_EQ(sent_forward(), 2u);
}

// ---- Soft limits --------------------------------------------------------------------------------

TEST_F(ChannelTest, SoftLimitsStopAtTheLimitAndNeverLoseAStep) {
  Channel channel;
  start(channel);
  channel.set_ratio(1, 80);                            // 80 steps per mm
  channel.set_upper_limit(0.25);                       // 20 steps
  channel.set_lower_limit(-0.125);                     // −10 steps
  channel.input_target_position.write(5.0, ABSOLUTE);  // 400 steps, far past the limit
  for (int frame = 0; frame < 100; ++frame) {
    hal_manual::run_frames(1);
    ASSERT_LE(channel.current_position, 20.0);
  }
  EXPECT_EQ(channel.current_position, 20.0);
  EXPECT_EQ(sent_forward(), 20u);
  EXPECT_EQ(channel.pulses_withheld_by_limits(), 80u);
  EXPECT_EQ(channel.is_outside_limits(), 1);

  channel.input_target_position.write(-5.0, ABSOLUTE);
  for (int frame = 0; frame < 100; ++frame) {
    hal_manual::run_frames(1);
    ASSERT_GE(channel.current_position, -10.0);
  }
  EXPECT_EQ(channel.current_position, -10.0);
  EXPECT_EQ(sent_reverse(), 30u);
  EXPECT_EQ(channel.is_outside_limits(), -1);

  channel.input_target_position.write(0.0, ABSOLUTE);
  hal_manual::run_frames(50);
  EXPECT_EQ(channel.current_position, 0.0);
  EXPECT_EQ(sent_forward(), 30u);  // physical pulses out = pulses back: no step lost
  EXPECT_EQ(sent_reverse(), 30u);
  EXPECT_EQ(channel.is_outside_limits(), 0);
}

TEST_F(ChannelTest, LimitsFollowALaterRatioAndCanBeDisabled) {
  Channel channel;
  start(channel);
  channel.set_upper_limit(0.25);
  channel.set_ratio(1, 80);                            // the limit becomes 20 steps
  channel.input_target_position.write(1.0, ABSOLUTE);  // 80 steps
  hal_manual::run_frames(100);
  EXPECT_EQ(channel.current_position, 20.0);

  channel.disable_limits();
  hal_manual::run_frames(100);
  EXPECT_EQ(channel.current_position, 80.0);
  EXPECT_EQ(channel.is_outside_limits(), 0);
}

// ---- Filtering ----------------------------------------------------------------------------------

TEST_F(ChannelTest, FilteringIsAnExponentialAverage) {
  Channel channel;
  start(channel);
  channel.enable_filtering(4);  // f = (3 f + target) / 4
  channel.input_target_position.write(8.0, ABSOLUTE);
  const double expected_filtered[] = {2.0, 3.5, 4.625, 5.46875};
  double expected_current = 0.0;
  for (double filtered : expected_filtered) {
    hal_manual::run_frames(1);
    expected_current += 1.0;
    EXPECT_EQ(channel.filtered_target_position, filtered);
    EXPECT_EQ(channel.current_position, expected_current);
  }
}

TEST_F(ChannelTest, DefaultFilterUsesTwentySamplesAndSumsBothInputs) {
  Channel channel;
  start(channel);
  channel.enable_filtering();
  channel.input_target_position.write(15.0, ABSOLUTE);
  channel.input_target_position_2.write(5.0, ABSOLUTE);
  hal_manual::run_frames(1);
  EXPECT_DOUBLE_EQ(channel.filtered_target_position, 1.0);  // 20 / 20
  hal_manual::run_frames(1);
  EXPECT_DOUBLE_EQ(channel.filtered_target_position, 1.95);  // (19 + 20) / 20

  channel.disable_filtering();
  hal_manual::run_frames(30);
  EXPECT_EQ(channel.filtered_target_position, 20.0);
  EXPECT_EQ(channel.current_position, 20.0);
}

// ---- Enable, begin, deep push ------------------------------------------------------------------

TEST_F(ChannelTest, DisabledChannelEmitsNothing) {
  Channel channel;
  start(channel);
  channel.disable();
  channel.input_target_position.write(10.0, ABSOLUTE);
  hal_manual::run_frames(50);
  EXPECT_EQ(sent_total(), 0u);
  EXPECT_EQ(channel.current_position, 0.0);

  channel.enable();
  hal_manual::run_frames(20);
  EXPECT_EQ(sent_forward(), 10u);
  EXPECT_EQ(channel.current_position, 10.0);
}

TEST_F(ChannelTest, ChannelWithoutPortStillRuns) {
  Channel channel;
  ASSERT_EQ(channel.begin(), Status::kOk);
  EXPECT_EQ(engine().count(Stage::kChannels), 1u);
  ASSERT_EQ(dance_start(), Status::kOk);
  channel.input_target_position.write(5.0, ABSOLUTE);
  hal_manual::run_frames(10);
  EXPECT_EQ(channel.current_position, 5.0);
  EXPECT_EQ(channel.pulses_forward(), 5u);
  EXPECT_EQ(sent_total(), 0u);
}

TEST_F(ChannelTest, BeginRefusesAnUnknownSignal) {
  Channel channel;
  EXPECT_EQ(channel.begin(&port, 6), Status::kBadArgument);
  EXPECT_EQ(engine().count(Stage::kChannels), 0u);
}

TEST_F(ChannelTest, DeepPushRezeroesTheErrorWithoutStepping) {
  Channel channel;
  start(channel);
  channel.set_ratio(1, 80);
  channel.input_target_position.reset_deep(5.0);
  EXPECT_DOUBLE_EQ(channel.target_position, 400.0);
  EXPECT_DOUBLE_EQ(channel.current_position, 400.0);
  EXPECT_DOUBLE_EQ(channel.filtered_target_position, 400.0);
  channel.input_target_position_2.reset_deep(0.5);
  EXPECT_DOUBLE_EQ(channel.current_position, 440.0);
  hal_manual::run_frames(20);
  EXPECT_EQ(sent_total(), 0u);
  EXPECT_DOUBLE_EQ(channel.input_target_position.read_deep(), 5.0);  // world, not 400 steps
  EXPECT_DOUBLE_EQ(channel.input_target_position.pull_deep(), 5.0);

  channel.input_target_position.write(0.25);  // motion after the re-zero is relative to it
  hal_manual::run_frames(40);
  EXPECT_EQ(sent_forward(), 20u);
  EXPECT_DOUBLE_EQ(channel.current_position, 460.0);
}

}  // namespace
}  // namespace stepdance
