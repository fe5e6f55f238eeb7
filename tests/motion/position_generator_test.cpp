// Unit tests of PositionGenerator: speed-limited travel, exact arrival, go() modes, resets.
#include <gtest/gtest.h>

#include "stepdance/core/fault.hpp"

#include "hal_manual.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/io/output_port.hpp"
#include "stepdance/motion/channel.hpp"
#include "stepdance/motion/position_generator.hpp"
#include "support/engine_fixture.hpp"

namespace stepdance {
namespace {

constexpr double kTolerance = 1e-9;

class PositionGeneratorTest : public test_support::EngineFixture {
 protected:
  void start() {
    ASSERT_EQ(generator.begin(), Status::kOk);
    ASSERT_EQ(dance_start(), Status::kOk);
  }
  double position() const { return generator.output.read(ABSOLUTE); }

  PositionGenerator generator;
};

TEST_F(PositionGeneratorTest, TravelsAtSpeedAndLandsExactly) {
  start();
  // 390.625 units/s × 40 µs = 0.015625 per frame: 64 full frames reach 1.0, the 65th the rest.
  generator.go(1.01, ABSOLUTE, 390.625);
  for (int frame = 1; frame <= 64; ++frame) {
    hal_manual::run_frames(1);
    ASSERT_NEAR(generator.output.read(INCREMENTAL), 0.015625, kTolerance);
  }
  EXPECT_NEAR(position(), 1.0, kTolerance);
  EXPECT_FALSE(generator.is_idle());
  hal_manual::run_frames(1);
  EXPECT_EQ(position(), 1.01);
  EXPECT_NEAR(generator.output.read(INCREMENTAL), 0.01, kTolerance);
  EXPECT_TRUE(generator.is_idle());
  hal_manual::run_frames(10);
  EXPECT_EQ(position(), 1.01);
}

TEST_F(PositionGeneratorTest, IncrementalAddsToTheTargetAndAbsoluteReplacesIt) {
  start();
  generator.set_speed(100);
  generator.go(1.0, INCREMENTAL);
  generator.go(0.5, INCREMENTAL);
  EXPECT_EQ(generator.target(), 1.5);
  hal_manual::run_frames(500);
  EXPECT_EQ(position(), 1.5);
  generator.go(-2.0, ABSOLUTE);
  hal_manual::run_frames(1000);
  EXPECT_EQ(position(), -2.0);
}

TEST_F(PositionGeneratorTest, SpeedArgumentIsStoredAndItsMagnitudeUsed) {
  start();
  generator.go(1.0, ABSOLUTE, -250.0);  // 0.01 per frame whatever the sign
  EXPECT_EQ(generator.speed_units_per_sec, -250.0f);
  hal_manual::run_frames(50);
  EXPECT_NEAR(position(), 0.5, kTolerance);
  generator.set_speed(0);
  hal_manual::run_frames(50);
  EXPECT_NEAR(position(), 0.5, kTolerance);
}

TEST_F(PositionGeneratorTest, DrivesAChannelStepByStep) {
  OutputPort port;
  ASSERT_EQ(port.begin(OUTPUT_C), Status::kOk);
  Channel channel;
  ASSERT_EQ(channel.begin(&port, SIGNAL_Z), Status::kOk);
  channel.set_ratio(1, 80);
  generator.output.map(&channel.input_target_position);
  start();
  generator.go(1.0, INCREMENTAL, 100);  // 250 frames, 0.32 step per frame
  hal_manual::run_frames(300);
  EXPECT_EQ(port.pulses_sent(SIGNAL_Z, DIRECTION_FORWARD), 80u);
  EXPECT_EQ(port.pulses_sent(SIGNAL_Z, DIRECTION_REVERSE), 0u);
  EXPECT_NEAR(channel.current_position, 80.0, kTolerance);
}

TEST_F(PositionGeneratorTest, ResetOfTheOutputNeverMoves) {
  start();
  generator.go(1.0, ABSOLUTE, 100);
  hal_manual::run_frames(300);
  generator.output.reset_deep(5.0);  // no peer: only the generator's own state changes
  hal_manual::run_frames(10);
  EXPECT_EQ(position(), 5.0);
  EXPECT_EQ(generator.target(), 5.0);
  EXPECT_EQ(generator.output.read(INCREMENTAL), 0.0);
  EXPECT_TRUE(generator.is_idle());
}

TEST_F(PositionGeneratorTest, GlobalGoAdoptsTheChannelPositionFirst) {
  OutputPort port;
  ASSERT_EQ(port.begin(OUTPUT_C), Status::kOk);
  Channel channel;
  ASSERT_EQ(channel.begin(&port, SIGNAL_Z), Status::kOk);
  channel.set_ratio(1, 80);
  generator.output.map(&channel.input_target_position);
  start();
  channel.input_target_position.reset_deep(3.0);  // e.g. homing set the axis to 3 mm
  hal_manual::run_frames(10);
  EXPECT_EQ(port.pulses_sent(SIGNAL_Z, DIRECTION_FORWARD), 0u);

  generator.go(4.0, GLOBAL, 100);  // from 3 to 4, not from the generator's own 0
  EXPECT_EQ(generator.target(), 4.0);
  // The next frame applies the command: it adopts 3 mm, then takes its first 0.004 mm step.
  hal_manual::run_frames(1);
  EXPECT_NEAR(generator.output.read(ABSOLUTE), 3.004, 1e-12);
  hal_manual::run_frames(299);
  EXPECT_EQ(port.pulses_sent(SIGNAL_Z, DIRECTION_FORWARD), 80u);
  EXPECT_EQ(port.pulses_sent(SIGNAL_Z, DIRECTION_REVERSE), 0u);
  EXPECT_DOUBLE_EQ(channel.current_position, 320.0);
}

TEST_F(PositionGeneratorTest, CommandsQueueUpToTheCapacityThenAreRefusedAndReported) {
  start();
  for (size_t i = 0; i < PositionGenerator::kCommandCapacity; ++i) {
    EXPECT_EQ(generator.go(1.0, INCREMENTAL, 1000), Status::kOk);
  }
  EXPECT_EQ(generator.go(1.0, INCREMENTAL), Status::kFull);  // refused, nothing overwritten
  EXPECT_EQ(warning_count(), 1u);
  EXPECT_EQ(generator.target(), static_cast<double>(PositionGenerator::kCommandCapacity));
  EXPECT_FALSE(generator.is_idle());
  hal_manual::run_frames(1000);
  EXPECT_EQ(position(), static_cast<double>(PositionGenerator::kCommandCapacity));
  EXPECT_TRUE(generator.is_idle());
}

}  // namespace
}  // namespace stepdance
