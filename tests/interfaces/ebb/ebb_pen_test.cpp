// EbbPen on its own: SC's pen parameters and the servo moves of SP, TP and S2 (ebb-protocol.md
// "SC" and "SP"; positions in 1/12 µs, one tick 40 µs so a millisecond is 25 ticks).
#include <gtest/gtest.h>

#include "stepdance/interfaces/ebb/ebb_pen.hpp"

namespace stepdance::ebb {
namespace {

TEST(EbbPenTest, UpAndDownGoToTheirPositionsAtTheirRates) {
  EbbPen pen;
  const EbbMove up = pen.move(true, 0);
  EXPECT_EQ(up.kind, EbbMove::Kind::kServo);
  EXPECT_EQ(up.servo_target, 20000);  // 1.667 ms × 12 per µs
  EXPECT_TRUE(up.pen_up);
  const EbbMove down = pen.move(false, 250);
  EXPECT_EQ(down.servo_target, 16000);  // 1.333 ms × 12 per µs
  EXPECT_FALSE(down.pen_up);
  EXPECT_EQ(down.ticks, 250u * 25u);  // 250 ms of waiting at 25 ticks per ms
  EXPECT_EQ(down.servo_rate, 0);      // at once until SC,12 says otherwise
}

TEST(EbbPenTest, ScSetsOnlyThePensParameters) {
  EbbPen pen;
  EXPECT_TRUE(pen.configure(4, 14000));
  EXPECT_TRUE(pen.configure(5, 18000));
  EXPECT_TRUE(pen.configure(10, 300));  // both rates
  EXPECT_EQ(pen.up_rate(), 300);
  EXPECT_EQ(pen.down_rate(), 300);
  EXPECT_TRUE(pen.configure(12, 150));  // the down rate alone
  EXPECT_EQ(pen.up_rate(), 300);
  EXPECT_EQ(pen.down_rate(), 150);
  EXPECT_FALSE(pen.configure(1, 1));  // SC,1 routes the solenoid: not the pen's
  EXPECT_EQ(pen.up_position(), 14000);
  EXPECT_EQ(pen.down_position(), 18000);
  EXPECT_EQ(pen.move(false, 0).servo_rate, 150);
  EXPECT_EQ(pen.move(true, 0).servo_rate, 300);
}

// The middle of 20000 and 16000 is 18000; a position counts as up only beyond it on the up side, and
// the sides swap when the up position is the lower pulse width (the EBB's own 12000 / 16000 defaults).
TEST(EbbPenTest, AnS2PositionIsUpOnTheUpPositionsSideOfTheMiddle) {
  EbbPen pen;
  EXPECT_TRUE(pen.position_move(18001, 0, 0).pen_up);
  EXPECT_FALSE(pen.position_move(18000, 0, 0).pen_up);
  EXPECT_FALSE(pen.position_move(9000, 0, 0).pen_up);
  pen.configure(4, 12000);
  pen.configure(5, 16000);
  EXPECT_TRUE(pen.position_move(13999, 0, 0).pen_up);
  EXPECT_FALSE(pen.position_move(14001, 0, 0).pen_up);
  const EbbMove move = pen.position_move(15000, 42, 10);
  EXPECT_EQ(move.servo_target, 15000);
  EXPECT_EQ(move.servo_rate, 42);
  EXPECT_EQ(move.ticks, 250u);
}

TEST(EbbPenTest, TheCommandedStateIsWhatTheLastQueuedCommandAskedFor) {
  EbbPen pen;
  EXPECT_TRUE(pen.commanded_up());  // power-on: up
  pen.commanded(false);
  EXPECT_FALSE(pen.commanded_up());
  pen.lift_now(true);  // SP,3: up now, and down becomes up
  EXPECT_TRUE(pen.commanded_up());
  EXPECT_EQ(pen.down_position(), 20000);
  pen.commanded(false);
  pen.reset();
  EXPECT_TRUE(pen.commanded_up());
}

// 1.5 ms is 18000 twelfths of a µs: zero; 20000/12 µs is 166.67 µs above it.
TEST(EbbPenTest, ServoPositionsBecomeStepsFromNeutral) {
  EXPECT_DOUBLE_EQ(EbbPen::steps_from_neutral(18000.0), 0.0);
  EXPECT_NEAR(EbbPen::steps_from_neutral(20000.0), 500.0 / 3.0, 1e-12);
  EXPECT_NEAR(EbbPen::steps_from_neutral(12000.0), -500.0, 1e-12);
}

}  // namespace
}  // namespace stepdance::ebb
