// Encoder: ratio, inversion, set/reset without motion, and latches that never drag backwards.
#include "stepdance/io/encoder.hpp"

#include <gtest/gtest.h>

#include "hal_manual.hpp"
#include "stepdance/core/dance.hpp"
#include "support/collector_block.hpp"
#include "support/engine_fixture.hpp"

namespace stepdance {
namespace {

using test_support::Collector;

class EncoderTest : public test_support::EngineFixture {
 protected:
  // Starts ENCODER_1 feeding the collector, then the engine.
  void start(Encoder& encoder) {
    ASSERT_EQ(encoder.begin(ENCODER_1), Status::kOk);
    sink.begin();
    encoder.output.map(&sink.input);
    ASSERT_EQ(dance_start(), Status::kOk);
  }
  // Moves the hardware count and runs one frame; returns the change that reached the sink.
  double turn_to(int32_t hardware_count) {
    hal_manual::set_quadrature(ENCODER_1, hardware_count);
    hal_manual::run_frames(1);
    return sink.last_change();
  }
  Collector sink;
};

TEST_F(EncoderTest, RatioConvertsCountsToWorldUnits) {
  Encoder encoder;
  start(encoder);
  encoder.set_ratio(24, 2400);  // 0.01 mm per count
  EXPECT_DOUBLE_EQ(turn_to(300), 3.0);
  EXPECT_DOUBLE_EQ(encoder.read(), 3.0);
  EXPECT_DOUBLE_EQ(turn_to(250), -0.5);
  EXPECT_DOUBLE_EQ(sink.position, 2.5);
}

TEST_F(EncoderTest, SingleArgumentRatioRescalesWithoutMotion) {
  Encoder encoder;
  start(encoder);
  EXPECT_DOUBLE_EQ(turn_to(300), 300.0);  // default ratio: one world unit per count
  encoder.set_ratio(0.5);
  EXPECT_DOUBLE_EQ(encoder.read(), 150.0);
  EXPECT_DOUBLE_EQ(turn_to(300), 0.0);  // a new ratio alone moves nothing downstream
  EXPECT_DOUBLE_EQ(turn_to(310), 5.0);
  EXPECT_DOUBLE_EQ(sink.position, 305.0);
}

TEST_F(EncoderTest, CountPresentAtBeginIsNotPushedAsMotion) {
  hal_manual::set_quadrature(ENCODER_1, 500);
  Encoder encoder;
  start(encoder);
  hal_manual::run_frames(1);
  EXPECT_DOUBLE_EQ(encoder.read(), 500.0);
  EXPECT_DOUBLE_EQ(sink.position, 0.0);
  EXPECT_DOUBLE_EQ(turn_to(503), 3.0);
}

TEST_F(EncoderTest, InvertReversesTheDirectionAndKeepsTheReading) {
  Encoder encoder;
  encoder.invert();
  start(encoder);
  EXPECT_TRUE(encoder.is_inverted());
  EXPECT_DOUBLE_EQ(turn_to(100), -100.0);
  EXPECT_DOUBLE_EQ(encoder.read(), -100.0);

  encoder.invert(false);  // the hardware count is negated, so the reading stays −100
  EXPECT_FALSE(encoder.is_inverted());
  EXPECT_EQ(hal::quadrature_read(ENCODER_1), -100);
  hal_manual::run_frames(1);
  EXPECT_DOUBLE_EQ(sink.last_change(), 0.0);
  EXPECT_DOUBLE_EQ(turn_to(-90), 10.0);
  EXPECT_DOUBLE_EQ(sink.position, -90.0);
}

TEST_F(EncoderTest, InvertingTwiceStaysInverted) {
  Encoder encoder;
  encoder.invert();
  encoder.invert();  // the original toggled back here
  start(encoder);
  EXPECT_TRUE(encoder.is_inverted());
  EXPECT_DOUBLE_EQ(turn_to(40), -40.0);
}

TEST_F(EncoderTest, SetWithInvertProducesNoJump) {
  Encoder encoder;
  start(encoder);
  encoder.set_ratio(0.5);
  encoder.invert();
  EXPECT_DOUBLE_EQ(turn_to(-40), 20.0);

  encoder.set(10.0);  // 20 counts; inverted, so the hardware holds −20
  EXPECT_EQ(hal::quadrature_read(ENCODER_1), -20);
  EXPECT_DOUBLE_EQ(encoder.read(), 10.0);
  hal_manual::run_frames(1);
  EXPECT_DOUBLE_EQ(sink.last_change(), 0.0);  // the original jumped by 2 × 10 here
  hal_manual::run_frames(1);
  EXPECT_DOUBLE_EQ(sink.last_change(), 0.0);
  EXPECT_DOUBLE_EQ(turn_to(-22), 1.0);
  EXPECT_DOUBLE_EQ(sink.position, 21.0);
  EXPECT_DOUBLE_EQ(encoder.read(), 11.0);
}

TEST_F(EncoderTest, ResetZeroesTheReadingWithoutMotion) {
  Encoder encoder;
  start(encoder);
  EXPECT_DOUBLE_EQ(turn_to(42), 42.0);
  encoder.reset();
  EXPECT_EQ(hal::quadrature_read(ENCODER_1), 0);
  EXPECT_DOUBLE_EQ(encoder.read(), 0.0);
  hal_manual::run_frames(2);
  EXPECT_DOUBLE_EQ(sink.position, 42.0);
  EXPECT_DOUBLE_EQ(turn_to(-3), -3.0);
  EXPECT_DOUBLE_EQ(sink.position, 39.0);
}

TEST_F(EncoderTest, MaxLatchClampsWithoutBackwardDrag) {
  Encoder encoder;
  start(encoder);
  encoder.set_latch(10.0, MAX);
  EXPECT_TRUE(encoder.max_latch_enabled);
  EXPECT_EQ(encoder.max_latch_value, 10);

  EXPECT_DOUBLE_EQ(turn_to(8), 8.0);
  EXPECT_DOUBLE_EQ(turn_to(12), 2.0);              // stops at the latch: +2, not +4 then −2
  EXPECT_EQ(hal::quadrature_read(ENCODER_1), 10);  // over-travel written back
  hal_manual::run_frames(1);
  EXPECT_DOUBLE_EQ(sink.last_change(), 0.0);
  EXPECT_DOUBLE_EQ(turn_to(15), 0.0);  // pushing further still moves nothing
  EXPECT_DOUBLE_EQ(turn_to(7), -3.0);  // backing off 3 counts from the latch moves −3 at once
  EXPECT_DOUBLE_EQ(sink.position, 7.0);
  EXPECT_DOUBLE_EQ(encoder.read(), 7.0);

  encoder.clear_latch(MAX);
  EXPECT_DOUBLE_EQ(turn_to(30), 23.0);
}

TEST_F(EncoderTest, MinLatchWorksInWorldUnitsWithInversion) {
  Encoder encoder;
  start(encoder);
  encoder.set_ratio(0.5);
  encoder.invert();
  encoder.set_latch(-5.0, MIN);  // −10 counts
  EXPECT_EQ(encoder.min_latch_value, -10);

  EXPECT_DOUBLE_EQ(turn_to(30), -5.0);             // logical −30 clamped to −10
  EXPECT_EQ(hal::quadrature_read(ENCODER_1), 10);  // inverted: the hardware holds +10
  EXPECT_DOUBLE_EQ(turn_to(14), 0.0);
  EXPECT_DOUBLE_EQ(turn_to(8), 1.0);  // logical −8: two counts (1.0) above the latch
  EXPECT_DOUBLE_EQ(sink.position, -4.0);
}

TEST_F(EncoderTest, PantographHomingSetsAndLatchesAtTheSameCount) {
  Encoder encoder;
  start(encoder);
  encoder.set_ratio(1.0, 400);  // 400 counts per world unit
  encoder.set(-1.0);
  encoder.set_latch(-1.0, MIN);
  EXPECT_EQ(hal::quadrature_read(ENCODER_1), -400);
  hal_manual::run_frames(3);
  EXPECT_DOUBLE_EQ(sink.position, 0.0);
  EXPECT_DOUBLE_EQ(encoder.read(), -1.0);
  EXPECT_DOUBLE_EQ(turn_to(-500), 0.0);
  EXPECT_DOUBLE_EQ(turn_to(-300), 0.25);
}

TEST_F(EncoderTest, UnknownDecoderIsRefused) {
  Encoder encoder;
  EXPECT_EQ(encoder.begin(ENCODER_A), Status::kNoSuchPin);
  EXPECT_EQ(engine().count(Stage::kPreChannel), 0u);
  Encoder second;
  EXPECT_EQ(second.begin(ENCODER_2), Status::kOk);
  hal_manual::set_quadrature(ENCODER_2, 7);
  ASSERT_EQ(dance_start(), Status::kOk);
  hal_manual::run_frames(1);
  EXPECT_DOUBLE_EQ(second.read(), 7.0);
}

}  // namespace
}  // namespace stepdance
