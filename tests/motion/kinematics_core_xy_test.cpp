// Tests of KinematicsCoreXY and of deep synchronisation through generators, CoreXY and channels.
#include <gtest/gtest.h>

#include "hal_manual.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/io/output_port.hpp"
#include "stepdance/motion/channel.hpp"
#include "stepdance/motion/kinematics_core_xy.hpp"
#include "stepdance/motion/position_generator.hpp"
#include "support/engine_fixture.hpp"

namespace stepdance {
namespace {

constexpr double kTolerance = 1e-9;

// generator_x, generator_y → CoreXY → channel_a (OUTPUT_A), channel_b (OUTPUT_B), 80 steps/mm.
class CoreXYMachine : public test_support::EngineFixture {
 protected:
  void SetUp() override {
    EngineFixture::SetUp();
    ASSERT_EQ(port_a.begin(OUTPUT_A), Status::kOk);
    ASSERT_EQ(port_b.begin(OUTPUT_B), Status::kOk);
    ASSERT_EQ(channel_a.begin(&port_a, SIGNAL_X), Status::kOk);
    ASSERT_EQ(channel_b.begin(&port_b, SIGNAL_X), Status::kOk);
    channel_a.set_ratio(1, 80);
    channel_b.set_ratio(1, 80);
    ASSERT_EQ(generator_x.begin(), Status::kOk);
    ASSERT_EQ(generator_y.begin(), Status::kOk);
    ASSERT_EQ(kinematics.begin(), Status::kOk);
    generator_x.output.map(&kinematics.input_x);
    generator_y.output.map(&kinematics.input_y);
    kinematics.output_a.map(&channel_a.input_target_position);
    kinematics.output_b.map(&channel_b.input_target_position);
    ASSERT_EQ(dance_start(), Status::kOk);
  }

  uint32_t pulses(const OutputPort& port, uint8_t direction) const { return port.pulses_sent(SIGNAL_X, direction); }
  uint32_t all_pulses() const {
    return pulses(port_a, DIRECTION_FORWARD) + pulses(port_a, DIRECTION_REVERSE) + pulses(port_b, DIRECTION_FORWARD) +
           pulses(port_b, DIRECTION_REVERSE);
  }

  OutputPort port_a;
  OutputPort port_b;
  Channel channel_a;
  Channel channel_b;
  PositionGenerator generator_x;
  PositionGenerator generator_y;
  KinematicsCoreXY kinematics;
};

// ---- Forward map --------------------------------------------------------------------------------

TEST_F(CoreXYMachine, CoreXYForwardMapDrivesBothMotors) {
  kinematics.input_x.write(2.0);
  kinematics.input_y.write(0.5);
  hal_manual::run_frames(1);
  EXPECT_EQ(kinematics.output_a.read(ABSOLUTE), 2.5);
  EXPECT_EQ(kinematics.output_b.read(ABSOLUTE), 1.5);
  EXPECT_DOUBLE_EQ(channel_a.target_position, 200.0);
  EXPECT_DOUBLE_EQ(channel_b.target_position, 120.0);
  hal_manual::run_frames(300);
  EXPECT_EQ(pulses(port_a, DIRECTION_FORWARD), 200u);
  EXPECT_EQ(pulses(port_b, DIRECTION_FORWARD), 120u);

  kinematics.input_y.write(-2.0);  // y = −1.5: a = 0.5, b = 3.5
  hal_manual::run_frames(300);
  EXPECT_DOUBLE_EQ(channel_a.current_position, 40.0);
  EXPECT_DOUBLE_EQ(channel_b.current_position, 280.0);
}

TEST_F(CoreXYMachine, CoreXYComputesInWorldUnitsWhateverThePortRatios) {
  kinematics.input_x.set_ratio(2.0, 1);   // x is held in units of 2 mm
  kinematics.output_a.set_ratio(0.5, 1);  // a is held in units of 0.5 mm
  kinematics.input_x.write(3.0);          // 3 mm
  hal_manual::run_frames(1);
  EXPECT_EQ(kinematics.input_x.read_target(), 1.5);
  EXPECT_EQ(kinematics.output_a.read_target(), 6.0);
  EXPECT_EQ(kinematics.output_a.read(ABSOLUTE), 3.0);
  EXPECT_DOUBLE_EQ(channel_a.target_position, 240.0);
  EXPECT_DOUBLE_EQ(channel_b.target_position, 240.0);
  EXPECT_DOUBLE_EQ(kinematics.input_x.read_deep(), 3.0);

  kinematics.input_x.reset_deep(10.0);
  EXPECT_EQ(kinematics.input_x.read_target(), 5.0);
  EXPECT_EQ(kinematics.output_a.read_target(), 20.0);
  EXPECT_DOUBLE_EQ(channel_a.current_position, 800.0);
  EXPECT_DOUBLE_EQ(kinematics.input_x.read_deep(), 10.0);
}

// ---- Deep push ----------------------------------------------------------------------------------

TEST_F(CoreXYMachine, DeepResetMovesChannelsWithoutAPulse) {
  hal_manual::run_frames(10);
  kinematics.input_x.reset_deep(10.0);  // a = 10, b = 10
  EXPECT_DOUBLE_EQ(channel_a.target_position, 800.0);
  EXPECT_DOUBLE_EQ(channel_a.current_position, 800.0);
  EXPECT_DOUBLE_EQ(channel_b.target_position, 800.0);
  EXPECT_DOUBLE_EQ(channel_b.current_position, 800.0);
  kinematics.input_y.reset_deep(2.5);  // a = 12.5, b = 7.5
  EXPECT_DOUBLE_EQ(channel_a.current_position, 1000.0);
  EXPECT_DOUBLE_EQ(channel_b.current_position, 600.0);
  hal_manual::run_frames(100);
  EXPECT_EQ(all_pulses(), 0u);
  EXPECT_DOUBLE_EQ(channel_a.target_position, 1000.0);
  EXPECT_DOUBLE_EQ(channel_b.target_position, 600.0);
}

// ---- Deep read and pull after motion ------------------------------------------------------------

TEST_F(CoreXYMachine, DeepReadAndPullAfterMotionAreInWorldUnits) {
  kinematics.input_x.reset_deep(10.0);
  kinematics.input_y.reset_deep(2.5);
  generator_x.go(1.0, INCREMENTAL, 100);
  generator_y.go(-0.5, INCREMENTAL, 100);
  hal_manual::run_frames(400);
  // a = 12.5 + 1 − 0.5 = 13 mm (+40 steps), b = 7.5 + 1 + 0.5 = 9 mm (+120 steps).
  EXPECT_EQ(pulses(port_a, DIRECTION_FORWARD), 40u);
  EXPECT_EQ(pulses(port_b, DIRECTION_FORWARD), 120u);
  EXPECT_EQ(pulses(port_a, DIRECTION_REVERSE) + pulses(port_b, DIRECTION_REVERSE), 0u);

  EXPECT_NEAR(channel_a.input_target_position.read_deep(), 13.0, kTolerance);
  EXPECT_NEAR(kinematics.input_x.read_deep(), 11.0, kTolerance);
  EXPECT_NEAR(kinematics.input_y.read_deep(), 2.0, kTolerance);
  EXPECT_NEAR(generator_x.output.read_deep(), 11.0, kTolerance);
  EXPECT_NEAR(generator_y.output.read_deep(), 2.0, kTolerance);
  EXPECT_NEAR(generator_x.output.read(ABSOLUTE), 1.0, kTolerance);  // read_deep changed nothing

  EXPECT_NEAR(generator_y.output.pull_deep(), 2.0, kTolerance);
  EXPECT_NEAR(generator_y.output.read(ABSOLUTE), 2.0, kTolerance);
  EXPECT_NEAR(generator_y.target(), 2.0, kTolerance);  // the target moved with the reset
  hal_manual::run_frames(100);
  EXPECT_EQ(all_pulses(), 160u);  // nothing moved
}

// ---- GLOBAL moves -------------------------------------------------------------------------------

TEST_F(CoreXYMachine, GlobalGoStartsFromWhereAnotherSourceLeftTheMachine) {
  PositionGenerator jog;  // a second source summed into x (fan-in), e.g. a knob
  ASSERT_EQ(jog.begin(), Status::kOk);
  jog.output.map(&kinematics.input_x);
  kinematics.input_x.reset_deep(10.0);
  generator_x.go(1.0, INCREMENTAL, 100);
  jog.go(3.0, INCREMENTAL, 100);
  hal_manual::run_frames(1000);
  EXPECT_NEAR(kinematics.input_x.read_deep(), 14.0, kTolerance);
  const uint32_t a_before = pulses(port_a, DIRECTION_FORWARD);
  const uint32_t b_before = pulses(port_b, DIRECTION_FORWARD);

  generator_x.go(15.0, GLOBAL, 100);  // adopts x = 14 in the next frame, then moves 1 mm
  hal_manual::run_frames(1);
  EXPECT_NEAR(generator_x.output.read(ABSOLUTE), 14.0 + 100 * 40e-6, kTolerance);
  hal_manual::run_frames(399);
  EXPECT_EQ(pulses(port_a, DIRECTION_FORWARD) - a_before, 80u);
  EXPECT_EQ(pulses(port_b, DIRECTION_FORWARD) - b_before, 80u);
  EXPECT_EQ(pulses(port_a, DIRECTION_REVERSE) + pulses(port_b, DIRECTION_REVERSE), 0u);
  EXPECT_NEAR(kinematics.input_x.read_deep(), 15.0, kTolerance);
}

TEST_F(CoreXYMachine, GlobalGoAfterHomingTheChannelsDeep) {
  kinematics.input_x.reset_deep(10.0);
  generator_x.go(2.0, INCREMENTAL, 100);
  hal_manual::run_frames(600);
  channel_a.input_target_position.reset_deep(0.0);  // homing: motors are now at a = b = 0
  channel_b.input_target_position.reset_deep(0.0);
  hal_manual::run_frames(10);
  EXPECT_DOUBLE_EQ(channel_a.current_position, 0.0);
  EXPECT_NEAR(kinematics.input_x.read_deep(), 0.0, kTolerance);
  const uint32_t before = all_pulses();

  generator_x.go(2.0, GLOBAL, 100);  // x from 0 to 2: a, b from 0 to 2 mm = 160 steps each
  hal_manual::run_frames(600);
  EXPECT_EQ(all_pulses() - before, 320u);
  EXPECT_DOUBLE_EQ(channel_a.current_position, 160.0);
  EXPECT_DOUBLE_EQ(channel_b.current_position, 160.0);
  EXPECT_NEAR(kinematics.input_y.read_deep(), 0.0, kTolerance);
}

}  // namespace
}  // namespace stepdance
