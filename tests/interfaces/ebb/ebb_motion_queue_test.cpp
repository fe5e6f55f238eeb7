// EbbMotionQueue on its own, driven frame by frame: depth, controls, the alarm, the stretch, and
// step timings worked out from the accumulator rule (ebb-protocol.md, LM row: a step each time
// the accumulator reaches 2^31). A rate of 2^29 is a step every 4th tick.
#include <gtest/gtest.h>

#include <string.h>

#include "stepdance/core/fault.hpp"
#include "stepdance/interfaces/ebb/ebb_motion_queue.hpp"
#include "support/engine_fixture.hpp"

namespace stepdance::ebb {
namespace {

constexpr int64_t kQuarterRate = int64_t{1} << 29;  // one step per 4 ticks
constexpr int64_t kFullRate = int64_t{1} << 31;     // one step per tick, 25 000 steps/s

EbbMove steps_move(uint32_t steps, int64_t rate) {
  EbbMove move;
  move.kind = EbbMove::Kind::kSteps;
  move.steps[0] = steps;
  move.rate[0] = rate;
  return move;
}

class EbbMotionQueueTest : public test_support::EngineFixture {
 protected:
  void SetUp() override {
    EngineFixture::SetUp();
    queue.begin(20000);
  }
  void frames(int count, uint32_t period_us = 40) {
    for (int i = 0; i < count; ++i) queue.run_frame(period_us);
  }
  int64_t motor1() const { return queue.executor().position_sixteenths(0); }

  EbbMotionQueue queue;
};

TEST_F(EbbMotionQueueTest, TheDepthAClientSeesStartsAtOneAndIsClamped) {
  EXPECT_TRUE(queue.push(steps_move(10, kQuarterRate), "SM"));
  EXPECT_FALSE(queue.push(steps_move(10, kQuarterRate), "SM"));  // depth 1: the second waits
  EXPECT_EQ(queue.waiting(), 1u);
  queue.set_depth(3);
  EXPECT_TRUE(queue.push(steps_move(10, kQuarterRate), "SM"));
  EXPECT_TRUE(queue.push(steps_move(10, kQuarterRate), "SM"));
  EXPECT_FALSE(queue.push(steps_move(10, kQuarterRate), "SM"));
  queue.set_depth(0);
  EXPECT_EQ(queue.depth(), 1u);
  queue.set_depth(1000);
  EXPECT_EQ(queue.depth(), EbbMotionQueue::kCapacity);
  EXPECT_EQ(EbbMotionQueue::kCapacity, 64u);
}

// 100 steps at one per 4 ticks end on tick 400: frame 400 at 40 µs, frame 1600 at 10 µs.
TEST_F(EbbMotionQueueTest, AMoveTakesItsStepsOnTheTicksTheAccumulatorGives) {
  ASSERT_TRUE(queue.push(steps_move(100, kQuarterRate), "LM"));
  frames(399);
  EXPECT_EQ(motor1(), 99);
  EXPECT_TRUE(queue.busy());
  EXPECT_TRUE(queue.motor_moving(0));
  EXPECT_FALSE(queue.motor_moving(1));
  frames(1);
  EXPECT_EQ(motor1(), 100);
  EXPECT_EQ(queue.global_steps(0), 100);
  frames(1);
  EXPECT_TRUE(queue.idle());
  EXPECT_EQ(queue.moves_started(), 1u);

  ASSERT_TRUE(queue.push(steps_move(100, kQuarterRate), "LM"));
  frames(1599, 10);
  EXPECT_EQ(motor1(), 199);
  frames(1, 10);
  EXPECT_EQ(motor1(), 200);
}

TEST_F(EbbMotionQueueTest, ProgressAndDurationFollowTheTicks) {
  ASSERT_TRUE(queue.push(steps_move(100, kQuarterRate), "LM"));
  frames(200);
  EXPECT_DOUBLE_EQ(queue.move_duration_s(), 400.0 / 25000.0);
  EXPECT_DOUBLE_EQ(queue.progress(), 0.5);
  frames(201);
  EXPECT_DOUBLE_EQ(queue.progress(), 1.0);
}

// ES: the move stops before the next tick and the moves behind it are flushed, yet counted as
// started so that waiting() is 0 again.
TEST_F(EbbMotionQueueTest, AStopFlushesTheFifoBeforeTheNextTick) {
  queue.set_depth(3);
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(queue.push(steps_move(100, kQuarterRate), "SM"));
  frames(10);  // ticks 4 and 8 stepped
  EXPECT_EQ(queue.waiting(), 2u);
  EXPECT_TRUE(queue.executing());
  queue.control(EbbControl::kStop);
  EXPECT_FALSE(queue.idle());  // the control is pending
  frames(1);
  EXPECT_EQ(motor1(), 2);
  EXPECT_FALSE(queue.busy());
  EXPECT_EQ(queue.waiting(), 0u);
  EXPECT_EQ(queue.moves_started(), 3u);
  EXPECT_TRUE(queue.idle());
}

TEST_F(EbbMotionQueueTest, AnAlarmStopsMotorMovesButLetsThePenMove) {
  queue.set_depth(4);
  ASSERT_TRUE(queue.push(steps_move(100, kQuarterRate), "SM"));
  frames(8);
  report_fault(FaultLevel::kAlarm, FaultReason::kLimitHit, "test");
  frames(1);
  EXPECT_FALSE(queue.motor_moving(0));
  EXPECT_EQ(motor1(), 2);
  EXPECT_EQ(queue.alarm_stops(), 1u);
  ASSERT_TRUE(queue.push(steps_move(100, kQuarterRate), "SM"));  // queued before the loop saw it
  EbbMove pen;
  pen.kind = EbbMove::Kind::kServo;
  pen.servo_target = 16000;
  ASSERT_TRUE(queue.push(pen, "SP"));
  frames(1);
  EXPECT_EQ(queue.alarm_stops(), 2u);
  EXPECT_EQ(motor1(), 2);
  EXPECT_DOUBLE_EQ(queue.executor().servo_position(), 16000.0);
  EXPECT_FALSE(queue.pen_up());
}

// At 1/8 stepping one EBB step is two channel steps: 1000 steps at one per tick ask 50 000 channel
// steps a second of 40 µs frames that carry 25 000, so the move runs twice as long: 2000 frames.
TEST_F(EbbMotionQueueTest, AMoveTooFastForTheFramesIsStretchedAndReportedOnce) {
  queue.set_depth(3);
  EbbMove eighth;
  eighth.kind = EbbMove::Kind::kEnable;
  eighth.microstep_mode = 2;
  ASSERT_TRUE(queue.push(eighth, "EM"));
  ASSERT_TRUE(queue.push(steps_move(1000, kFullRate), "SM"));
  frames(1999);
  EXPECT_EQ(motor1(), 999 * 2);
  frames(1);
  EXPECT_EQ(motor1(), 1000 * 2);
  EXPECT_EQ(queue.moves_stretched(), 1u);
  EXPECT_EQ(queue.motor_resolution(0), 8);
  EXPECT_EQ(queue.microstep_mode(), 2);
  WarningTally tally;
  ASSERT_TRUE(warning_tally(0, tally));
  EXPECT_STREQ(tally.source, "Eibotboard");
  EXPECT_STREQ(tally.detail,
               "SM move (1000, 0 steps) asked a motor for 50000 1/16 steps/s; the 40 us frames carry 25000: "
               "it ran 2.00x as long (later ones counted in moves_stretched)");
  frames(1);
  ASSERT_TRUE(queue.push(steps_move(10, kFullRate), "LM"));
  frames(30);
  EXPECT_EQ(queue.moves_stretched(), 2u);
  ASSERT_TRUE(warning_tally(0, tally));
  EXPECT_EQ(tally.count, 2u);  // the second only counted, its first report kept
}

TEST_F(EbbMotionQueueTest, PenNowClearStepsAndResetBypassTheFifo) {
  ASSERT_TRUE(queue.push(steps_move(100, kQuarterRate), "SM"));
  frames(40);
  queue.pen_now(15000, 0);
  queue.control(EbbControl::kClearSteps);
  frames(1);
  EXPECT_DOUBLE_EQ(queue.executor().servo_position(), 15000.0);
  EXPECT_EQ(queue.global_steps(0), 0);  // cleared; the motor's position is kept
  EXPECT_EQ(motor1(), 10);
  EXPECT_TRUE(queue.busy());  // the move goes on
  queue.set_depth(5);
  queue.reset(21000);
  EXPECT_EQ(queue.depth(), 1u);
  frames(1);
  EXPECT_FALSE(queue.busy());
  EXPECT_DOUBLE_EQ(queue.executor().servo_position(), 21000.0);
  EXPECT_EQ(motor1(), 0);  // power-on
}

// A servo slewing at 600 twelfths of a µs per 24 ms moves one per 40 µs tick: 16000 → 16010 takes 10.
TEST_F(EbbMotionQueueTest, IdleWaitsForTheServoToSettle) {
  EXPECT_TRUE(queue.idle());
  EbbMove pen;
  pen.kind = EbbMove::Kind::kServo;
  pen.servo_target = 20010;
  pen.servo_rate = 600;
  pen.pen_up = true;
  ASSERT_TRUE(queue.push(pen, "S2"));
  EXPECT_FALSE(queue.idle());
  frames(9);
  EXPECT_FALSE(queue.idle());
  frames(1);
  EXPECT_TRUE(queue.idle());
}

}  // namespace
}  // namespace stepdance::ebb
