// ChannelRatios: the steps/mm an interface output reaches through the sketch's map() calls, found by
// asking each block about its own ports (Block::world_units_per_step), never by its class name.
#include <gtest/gtest.h>

#include "stepdance/core/block.hpp"
#include "stepdance/motion/channel.hpp"
#include "stepdance/motion/channel_ratios.hpp"
#include "stepdance/motion/kinematics_core_xy.hpp"
#include "support/engine_fixture.hpp"

namespace stepdance {
namespace {

/// An interface's output, as the EBB and G-code have them.
class Source : public Block {
 public:
  Source() { output.begin(&state_, BLOCKPORT_OUTPUT, this); }
  BlockPort output;

 private:
  DecimalPosition state_ = 0;
};

/// A stepping block that is not a Channel: a step is `mm_per_step_` of its input.
class StepperLike : public Block {
 public:
  explicit StepperLike(double mm_per_step) : mm_per_step_(mm_per_step) { input.begin(&state_, BLOCKPORT_INPUT, this); }
  const char* type_name() const override { return "StepperLike"; }
  bool world_units_per_step(const BlockPort& port, double& world_units) const override {
    if (&port != &input) return false;
    world_units = mm_per_step_;
    return true;
  }
  BlockPort input;

 private:
  double mm_per_step_;
  DecimalPosition state_ = 0;
};

/// Calls itself "Channel" but steps nothing: the old lookup by type name took it for one.
class NamedChannel : public Block {
 public:
  NamedChannel() { input.begin(&state_, BLOCKPORT_INPUT, this); }
  const char* type_name() const override { return "Channel"; }
  BlockPort input;

 private:
  DecimalPosition state_ = 0;
};

class ChannelRatiosTest : public test_support::EngineFixture {};

TEST_F(ChannelRatiosTest, AChannelMappedFromTheOutputGivesItsMillimetresPerStep) {
  Source source;
  Channel channel;
  ASSERT_EQ(channel.begin(), Status::kOk);
  channel.set_ratio(25.4, 2032);  // 80 steps/mm
  source.output.map(&channel.input_target_position);
  ChannelRatios ratios;
  collect_channel_ratios(source.output, ratios);
  EXPECT_EQ(ratios.found, 1);
  EXPECT_DOUBLE_EQ(ratios.mm_per_step, 1.0 / 80.0);
  EXPECT_FALSE(ratios.disagree);
}

// Through a CoreXY block: both of its outputs' channels count, and an inverted one (a negative
// ratio) is the same size of step.
TEST_F(ChannelRatiosTest, ChannelsBehindAKinematicsCountAndTheirSignIsDropped) {
  Source source;
  KinematicsCoreXY kinematics;
  Channel a;
  Channel b;
  ASSERT_EQ(a.begin(), Status::kOk);
  ASSERT_EQ(b.begin(), Status::kOk);
  ASSERT_EQ(kinematics.begin(), Status::kOk);
  a.set_ratio(1.0, 100.0);
  b.set_ratio(-1.0, 100.0);
  source.output.map(&kinematics.input_x);
  kinematics.output_a.map(&a.input_target_position);
  kinematics.output_b.map(&b.input_target_position);
  ChannelRatios ratios;
  collect_channel_ratios(source.output, ratios);
  EXPECT_EQ(ratios.found, 2);
  EXPECT_DOUBLE_EQ(ratios.mm_per_step, 0.01);
  EXPECT_FALSE(ratios.disagree);
  b.set_ratio(1.0, 80.0);
  ChannelRatios differing;
  collect_channel_ratios(source.output, differing);
  EXPECT_TRUE(differing.disagree);
}

TEST_F(ChannelRatiosTest, AnyBlockThatStepsIsFoundWhateverItsName) {
  Source source;
  StepperLike stepper(0.025);
  source.output.map(&stepper.input);
  ChannelRatios ratios;
  collect_channel_ratios(source.output, ratios);
  EXPECT_EQ(ratios.found, 1);
  EXPECT_DOUBLE_EQ(ratios.mm_per_step, 0.025);
  // Pulled rather than pushed: the stepping input is mapped to the output.
  Source other;
  StepperLike puller(0.5);
  puller.input.map(&other.output);
  ChannelRatios pulled;
  collect_channel_ratios(other.output, pulled);
  EXPECT_EQ(pulled.found, 1);
  EXPECT_DOUBLE_EQ(pulled.mm_per_step, 0.5);
}

TEST_F(ChannelRatiosTest, ABlockNamedChannelThatStepsNothingIsNotOne) {
  Source source;
  NamedChannel impostor;
  source.output.map(&impostor.input);
  ChannelRatios ratios;
  collect_channel_ratios(source.output, ratios);
  EXPECT_EQ(ratios.found, 0);
}

TEST_F(ChannelRatiosTest, AChannelsOtherPortsAreNotSteps) {
  Channel channel;
  ASSERT_EQ(channel.begin(), Status::kOk);
  channel.set_ratio(1.0, 40.0);
  double world_units = 0.0;
  EXPECT_TRUE(channel.world_units_per_step(channel.input_target_position_2, world_units));
  EXPECT_DOUBLE_EQ(world_units, 1.0 / 40.0);
  BlockPort elsewhere;
  EXPECT_FALSE(channel.world_units_per_step(elsewhere, world_units));
}

}  // namespace
}  // namespace stepdance
