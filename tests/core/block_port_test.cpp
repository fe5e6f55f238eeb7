// Unit tests of the BlockPort buffer algebra, push/pull delivery and the reference worked example.
#include <gtest/gtest.h>

#include "hal_manual.hpp"
#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/io/output_port.hpp"
#include "stepdance/motion/channel.hpp"
#include "stepdance/motion/kinematics_core_xy.hpp"
#include "support/engine_fixture.hpp"

namespace stepdance {
namespace {

constexpr double kTolerance = 1e-9;

// ---- Buffer algebra on free-standing ports -----------------------------------------------------

TEST(BlockPortTest, IncrementalWritesAccumulate) {
  BlockPort port;
  port.write(1.5);
  port.write(2.25);
  port.update();
  EXPECT_EQ(port.read_target(), 3.75);
  EXPECT_EQ(port.read(INCREMENTAL), 3.75);
  EXPECT_EQ(port.read(ABSOLUTE), 3.75);
}

TEST(BlockPortTest, AbsoluteWritesOverwrite) {
  BlockPort port;
  port.write(5.0, ABSOLUTE);
  port.write(7.0, ABSOLUTE);
  port.update();
  EXPECT_EQ(port.read_target(), 7.0);
  EXPECT_EQ(port.read(INCREMENTAL), 7.0);
}

TEST(BlockPortTest, AbsoluteAndIncrementalWritesCombine) {
  BlockPort port;
  port.write(7.0, ABSOLUTE);
  port.update();
  port.write(10.0, ABSOLUTE);
  port.write(1.5);
  port.update();
  EXPECT_EQ(port.read_target(), 11.5);
  EXPECT_EQ(port.read(INCREMENTAL), 4.5);  // 11.5 − 7
}

TEST(BlockPortTest, EachUpdateStartsANewFrameOfIncrements) {
  BlockPort port;
  port.write(1.0);
  port.update();
  port.write(2.0);
  port.update();
  EXPECT_EQ(port.read_target(), 3.0);
  EXPECT_EQ(port.read(INCREMENTAL), 2.0);
  port.update();  // nothing written since: no change
  EXPECT_EQ(port.read_target(), 3.0);
  EXPECT_EQ(port.read(INCREMENTAL), 0.0);
}

TEST(BlockPortTest, UpdateOverridesDirectWritesToTheTarget) {
  DecimalPosition state = 0;
  BlockPort port;
  port.begin(&state);
  port.write(2.0);
  port.update();
  EXPECT_EQ(state, 2.0);
  state = 10.0;
  port.update();
  EXPECT_EQ(state, 2.0);
}

TEST(BlockPortTest, SetChangesTheTargetAndRecordsTheChange) {
  BlockPort port;
  port.set(4.0);
  EXPECT_EQ(port.read_target(), 4.0);
  EXPECT_EQ(port.read(INCREMENTAL), 4.0);
  port.set(1.5, INCREMENTAL);
  EXPECT_EQ(port.read_target(), 5.5);
  EXPECT_EQ(port.read(INCREMENTAL), 1.5);
  EXPECT_EQ(port.read(ABSOLUTE), 5.5);
}

TEST(BlockPortTest, ResetProducesNoDownstreamIncrement) {
  BlockPort output;
  BlockPort input;
  output.map(&input);
  output.set(5.0);
  output.push();
  input.update();
  EXPECT_EQ(input.read_target(), 5.0);

  output.reset(20.0);
  EXPECT_EQ(output.read(ABSOLUTE), 20.0);
  EXPECT_EQ(output.read(INCREMENTAL), 0.0);
  output.push();
  input.update();
  EXPECT_EQ(input.read_target(), 5.0);
  EXPECT_EQ(input.read(INCREMENTAL), 0.0);

  output.set(21.0);  // the next real change travels as usual
  output.push();
  input.update();
  EXPECT_EQ(input.read_target(), 6.0);
}

TEST(BlockPortTest, ReadBeforeAndAfterUpdate) {
  BlockPort port;
  port.write(3.0);
  port.update();

  port.write(2.0);  // pending
  EXPECT_EQ(port.read_target(), 3.0);
  EXPECT_EQ(port.read(INCREMENTAL), 2.0);
  EXPECT_EQ(port.read(ABSOLUTE), 5.0);
  port.update();
  EXPECT_EQ(port.read(INCREMENTAL), 2.0);
  EXPECT_EQ(port.read(ABSOLUTE), 5.0);

  port.write(10.0, ABSOLUTE);  // pending position 10 from 5
  EXPECT_EQ(port.read(INCREMENTAL), 5.0);
  EXPECT_EQ(port.read(ABSOLUTE), 10.0);
  port.write(1.0);
  EXPECT_EQ(port.read(INCREMENTAL), 6.0);
  EXPECT_EQ(port.read(ABSOLUTE), 11.0);
  port.update();
  EXPECT_EQ(port.read_target(), 11.0);
  EXPECT_EQ(port.read(INCREMENTAL), 6.0);
}

TEST(BlockPortTest, RatioConvertsBetweenWorldAndBlockUnits) {
  BlockPort port;
  port.set_ratio(25.4, 2032);  // 80 steps per mm
  port.write(1.0);             // mm
  port.update();
  EXPECT_NEAR(port.read_target(), 80.0, kTolerance);
  EXPECT_NEAR(port.read(ABSOLUTE), 1.0, kTolerance);
  port.set(160.0);  // steps
  EXPECT_NEAR(port.read(ABSOLUTE), 2.0, kTolerance);
  EXPECT_NEAR(port.read(INCREMENTAL), 1.0, kTolerance);
  EXPECT_NEAR(port.convert_world_to_block_units(0.5), 40.0, kTolerance);
  EXPECT_NEAR(port.convert_block_to_world_units(8.0), 0.1, kTolerance);
}

TEST(BlockPortTest, RatioIsKeptInDoublePrecision) {
  BlockPort port;
  port.set_ratio(25.4, 2874);
  EXPECT_EQ(port.ratio(), 25.4 / 2874.0);
  EXPECT_NE(port.ratio(), static_cast<double>(25.4f / 2874.0f));
}

TEST(BlockPortTest, FanInSumsTheIncrementsOfSeveralOutputs) {
  BlockPort first;
  BlockPort second;
  BlockPort input;
  first.map(&input);
  second.map(&input);
  first.set(1.0);
  second.set(2.5);
  first.push();
  second.push();
  input.update();
  EXPECT_EQ(input.read_target(), 3.5);

  second.set(3.0);  // only one source moves this frame
  first.push();
  second.push();
  input.update();
  EXPECT_EQ(input.read_target(), 4.0);
}

TEST(BlockPortTest, FanOutByPullDeliversEachChangeOnceToEveryPuller) {
  BlockPort output;
  BlockPort first;
  BlockPort second;
  first.map(&output);
  second.map(&output);
  output.set(1.0);
  for (BlockPort* input : {&first, &second}) {
    input->pull();
    input->update();
  }
  EXPECT_EQ(first.read_target(), 1.0);
  EXPECT_EQ(second.read_target(), 1.0);

  output.set(3.0);
  for (BlockPort* input : {&first, &second}) {
    input->pull();
    input->update();
  }
  EXPECT_EQ(first.read_target(), 3.0);
  EXPECT_EQ(second.read_target(), 3.0);
}

TEST(BlockPortTest, PullFromAnIdlePeerDoesNotCountAgain) {
  BlockPort output;
  BlockPort input;
  input.map(&output);
  output.set(2.0);
  for (int frame = 0; frame < 3; ++frame) {
    input.pull();
    input.update();
  }
  EXPECT_EQ(input.read_target(), 2.0);  // the original would hold 6 here
}

TEST(BlockPortTest, AbsoluteMappingCarriesPositions) {
  BlockPort output;
  BlockPort puller;
  puller.map(&output, ABSOLUTE);
  output.set(7.0);
  puller.pull();
  puller.update();
  EXPECT_EQ(puller.read_target(), 7.0);

  BlockPort pusher;
  BlockPort input;
  pusher.map(&input, GLOBAL);  // GLOBAL maps like ABSOLUTE
  pusher.set(4.0);
  pusher.push();
  input.update();
  EXPECT_EQ(input.read_target(), 4.0);
  input.write(1.0);  // an increment from elsewhere lasts one frame, the next position wins
  pusher.push();
  input.update();
  EXPECT_EQ(input.read_target(), 5.0);
  pusher.push();
  input.update();
  EXPECT_EQ(input.read_target(), 4.0);
}

TEST(BlockPortTest, MapReplacesThePreviousPeer) {
  BlockPort output;
  BlockPort old_input;
  BlockPort new_input;
  output.map(&old_input);
  output.map(&new_input);
  output.set(1.0);
  output.push();
  old_input.update();
  new_input.update();
  EXPECT_EQ(old_input.read_target(), 0.0);
  EXPECT_EQ(new_input.read_target(), 1.0);

  BlockPort old_source;
  BlockPort new_source;
  BlockPort puller;
  puller.map(&old_source);
  puller.map(&new_source);
  old_source.set(5.0);
  new_source.set(1.0);
  puller.pull();
  puller.update();
  EXPECT_EQ(puller.read_target(), 1.0);
}

TEST(BlockPortTest, DisabledPortDropsChangesInsteadOfDeferringThem) {
  BlockPort output;
  BlockPort input;
  output.map(&input);
  output.disable();
  output.set(1.0);
  output.push();
  input.update();
  EXPECT_EQ(input.read_target(), 0.0);
  output.enable();
  output.set(1.5);
  output.push();
  input.update();
  EXPECT_EQ(input.read_target(), 0.5);

  BlockPort source;
  BlockPort puller;
  puller.map(&source);
  puller.disable();
  source.set(2.0);
  puller.pull();
  puller.update();
  EXPECT_EQ(puller.read_target(), 0.0);
  puller.enable();
  source.set(3.0);
  puller.pull();
  puller.update();
  EXPECT_EQ(puller.read_target(), 1.0);
}

// ---- Reference §3.3: encoder → CoreXY → channel ------------------------------------------------

// Stands in for an encoder: its output follows `count`, set by the test between frames.
class CountSource : public Block {
 public:
  void begin(int32_t initial_count) {
    count = initial_count;
    state_ = initial_count;
    output.begin(&state_);
    register_in(Stage::kPreChannel);
  }
  void run() override {
    output.set(count);
    output.push();
  }

  BlockPort output;
  volatile int32_t count = 0;

 private:
  DecimalPosition state_ = 0;
};

class BlockPortWorkedExampleTest : public test_support::EngineFixture {};

TEST_F(BlockPortWorkedExampleTest, EncoderThroughCoreXYToChannel) {
  OutputPort port_a;
  ASSERT_EQ(port_a.begin(OUTPUT_A), Status::kOk);
  CountSource encoder;
  KinematicsCoreXY kinematics;
  Channel channel_a;
  ASSERT_EQ(channel_a.begin(&port_a, SIGNAL_X), Status::kOk);
  channel_a.set_ratio(25.4, 2032);     // 0.0125 mm per step
  encoder.output.set_ratio(24, 2400);  // 0.01 mm per count
  encoder.begin(100);
  ASSERT_EQ(kinematics.begin(), Status::kOk);
  encoder.output.map(&kinematics.input_x);
  kinematics.output_a.map(&channel_a.input_target_position);

  kinematics.input_x.reset_deep(1.00);  // x = 1.00 mm, y = 0 → channel at 80 steps, no error
  ASSERT_EQ(dance_start(), Status::kOk);
  hal_manual::run_frames(5);
  EXPECT_NEAR(channel_a.target_position, 80.0, kTolerance);
  EXPECT_EQ(channel_a.current_position, 80.0);
  EXPECT_EQ(port_a.pulses_sent(SIGNAL_X, DIRECTION_FORWARD), 0u);

  encoder.count = 103;
  hal_manual::run_frames(1);  // frame k
  EXPECT_NEAR(kinematics.input_x.read(INCREMENTAL), 0.03, kTolerance);
  EXPECT_NEAR(kinematics.input_x.read(ABSOLUTE), 1.03, kTolerance);
  EXPECT_NEAR(kinematics.output_a.read(INCREMENTAL), 0.03, kTolerance);
  EXPECT_NEAR(channel_a.input_target_position.read(INCREMENTAL), 0.03, kTolerance);
  EXPECT_NEAR(channel_a.target_position, 82.4, kTolerance);
  EXPECT_EQ(channel_a.current_position, 81.0);
  EXPECT_EQ(port_a.pulses_sent(SIGNAL_X, DIRECTION_FORWARD), 1u);
  EXPECT_NE(hal_manual::last_frame(OUTPUT_A).step_bits, 0u);

  hal_manual::run_frames(1);  // k + 1: error 1.4 steps
  EXPECT_EQ(channel_a.current_position, 82.0);
  EXPECT_EQ(port_a.pulses_sent(SIGNAL_X, DIRECTION_FORWARD), 2u);
  EXPECT_NE(hal_manual::last_frame(OUTPUT_A).step_bits, 0u);

  hal_manual::run_frames(1);  // k + 2: error 0.4 steps, inside the dead band
  EXPECT_EQ(channel_a.current_position, 82.0);
  EXPECT_EQ(port_a.pulses_sent(SIGNAL_X, DIRECTION_FORWARD), 2u);
  EXPECT_EQ(hal_manual::last_frame(OUTPUT_A).step_bits, 0u);
  EXPECT_NEAR(channel_a.target_position - channel_a.current_position, 0.4, kTolerance);
  EXPECT_NEAR(channel_a.input_target_position.read(ABSOLUTE), 1.03, kTolerance);
  EXPECT_EQ(port_a.pulses_sent(SIGNAL_X, DIRECTION_REVERSE), 0u);
}

}  // namespace
}  // namespace stepdance
