// EbbTickClock on its own: 40 µs EBB ticks counted out of frames of any period, and the stretch that
// keeps a move within one channel step per frame.
#include <gtest/gtest.h>

#include "stepdance/interfaces/ebb/ebb_tick_clock.hpp"

namespace stepdance::ebb {
namespace {

int ticks_in(EbbTickClock& clock, uint32_t period_us, int frames) {
  int ticks = 0;
  for (int i = 0; i < frames; ++i) ticks += clock.advance(period_us) ? 1 : 0;
  return ticks;
}

// One second of frames holds 25 000 ticks of 40 µs whatever the period: 25 000, 100 000 and 40 000
// frames of 40, 10 and 25 µs.
TEST(EbbTickClockTest, ASecondOfFramesIs25000TicksAtAnyPeriod) {
  EbbTickClock at_40;
  EXPECT_EQ(ticks_in(at_40, 40, 25000), 25000);
  EbbTickClock at_10;
  EXPECT_EQ(ticks_in(at_10, 10, 3), 0);  // the 4th 10 µs frame completes the first tick
  EXPECT_EQ(ticks_in(at_10, 10, 1), 1);
  EXPECT_EQ(ticks_in(at_10, 10, 100000 - 4), 25000 - 1);
  EbbTickClock at_25;
  EXPECT_EQ(ticks_in(at_25, 25, 8), 5);  // 200 µs: five ticks
  EXPECT_EQ(ticks_in(at_25, 25, 40000 - 8), 25000 - 5);
}

TEST(EbbTickClockTest, AMoveTheFramesCarryIsNotStretched) {
  EbbTickClock clock;
  EXPECT_FALSE(clock.fit(1.0, 40));  // one 1/16 step per tick, one frame per tick
  EXPECT_FALSE(clock.fit(4.0, 10));  // four frames of 10 µs carry four
  EXPECT_DOUBLE_EQ(clock.stretch(), 1.0);
  EXPECT_DOUBLE_EQ(EbbTickClock::carried_per_tick(25), 1.6);
}

// 1/8 stepping at the EBB's top rate is two 1/16 steps per tick: at 40 µs the move runs twice as
// long, one tick every second frame. 1.5 per tick gives 1.5 exactly (98304/65536).
TEST(EbbTickClockTest, AFasterMoveRunsOnALongerTick) {
  EbbTickClock clock;
  ASSERT_TRUE(clock.fit(2.0, 40));
  EXPECT_DOUBLE_EQ(clock.stretch(), 2.0);
  EXPECT_EQ(ticks_in(clock, 40, 1000), 500);
  EbbTickClock three_halves;
  ASSERT_TRUE(three_halves.fit(1.5, 40));
  EXPECT_DOUBLE_EQ(three_halves.stretch(), 1.5);
  EXPECT_EQ(ticks_in(three_halves, 40, 3000), 2000);
  EXPECT_FALSE(three_halves.fit(0.5, 40));  // the next move fits again: back to 40 µs ticks
  EXPECT_DOUBLE_EQ(three_halves.stretch(), 1.0);
}

// 5/3 is not a multiple of 1/65536: the stretch is rounded up (never faster than the channels).
TEST(EbbTickClockTest, AStretchIsRoundedUp) {
  EbbTickClock clock;
  ASSERT_TRUE(clock.fit(5.0 / 3.0, 40));
  EXPECT_DOUBLE_EQ(clock.stretch(), 109227.0 / 65536.0);  // ⌈65536 × 5/3⌉ = ⌈109226.67⌉
  EXPECT_GE(clock.stretch(), 5.0 / 3.0);
}

}  // namespace
}  // namespace stepdance::ebb
