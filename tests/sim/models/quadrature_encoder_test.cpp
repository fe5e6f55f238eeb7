// QuadratureEncoder: counts delivered over a turn, accumulation and query order.
#include <gtest/gtest.h>

#include "models/quadrature_encoder.hpp"

namespace stepdance::sim {
namespace {

TEST(QuadratureEncoder, CountsPerRevolutionAreFourTimesThePulses) {
  QuadratureEncoder knob;
  EXPECT_EQ(knob.pulses_per_revolution(), 600);
  EXPECT_EQ(knob.counts_per_revolution(), 2400);
  EXPECT_EQ(knob.count_at(5 * kSecond), 0);
}

TEST(QuadratureEncoder, ATurnDeliversWholeCountsEvenlyOverItsSpan) {
  QuadratureEncoder knob(600, 0);
  knob.turn(500 * kMillisecond, 2400, 1 * kSecond);
  EXPECT_EQ(knob.count_at(0), 0);
  EXPECT_EQ(knob.count_at(500 * kMillisecond), 0);
  // Count 1 arrives at ceil(1 s / 2400) = 416 667 ns into the turn.
  EXPECT_EQ(knob.count_at(500 * kMillisecond + 416666), 0);
  EXPECT_EQ(knob.count_at(500 * kMillisecond + 416667), 1);
  EXPECT_EQ(knob.count_at(501 * kMillisecond), 2);  // floor(2.4)
  EXPECT_EQ(knob.count_at(1 * kSecond), 1200);
  EXPECT_EQ(knob.count_at(1500 * kMillisecond - 1), 2399);
  EXPECT_EQ(knob.count_at(1500 * kMillisecond), 2400);
  EXPECT_EQ(knob.count_at(9 * kSecond), 2400);
  EXPECT_DOUBLE_EQ(knob.revolutions_at(9 * kSecond), 1.0);
}

TEST(QuadratureEncoder, NegativeTurnsCountDown) {
  QuadratureEncoder knob(600, 7);
  knob.turn(2 * kSecond, -100, 10 * kMillisecond);
  EXPECT_EQ(knob.count_at(2005 * kMillisecond), 7 - 50);
  EXPECT_EQ(knob.count_at(3 * kSecond), 7 - 100);
}

TEST(QuadratureEncoder, AnInstantTurnLandsAtItsStart) {
  QuadratureEncoder knob;
  knob.turn(1 * kSecond, 42, 0);
  EXPECT_EQ(knob.count_at(1 * kSecond - 1), 0);
  EXPECT_EQ(knob.count_at(1 * kSecond), 42);
}

TEST(QuadratureEncoder, OverlappingTurnsAddUp) {
  QuadratureEncoder knob;
  knob.turn(500 * kMillisecond, -1000, 1 * kSecond);
  knob.turn(0, 1000, 1 * kSecond);
  EXPECT_EQ(knob.count_at(750 * kMillisecond), 750 - 250);
  EXPECT_EQ(knob.count_at(1 * kSecond), 1000 - 500);
  EXPECT_EQ(knob.count_at(1250 * kMillisecond), 1000 - 750);
  EXPECT_EQ(knob.count_at(2 * kSecond), 0);
}

TEST(QuadratureEncoder, QueriesMayGoBackInTimeAndTurnsMayBeAddedLater) {
  QuadratureEncoder knob;
  knob.turn(0, 100, 100 * kMillisecond);
  EXPECT_EQ(knob.count_at(1 * kSecond), 100);
  EXPECT_EQ(knob.count_at(25 * kMillisecond), 25);
  knob.turn(10 * kMillisecond, 5, 0);
  EXPECT_EQ(knob.count_at(25 * kMillisecond), 30);
  EXPECT_EQ(knob.count_at(1 * kSecond), 105);
}

TEST(QuadratureEncoder, ForwardQueriesEveryFrameMatchTheFormula) {
  QuadratureEncoder knob;
  knob.turn(0, 2400, 1 * kSecond);
  for (SimTime t = 0; t <= 1 * kSecond; t += 40 * kMicrosecond) {
    ASSERT_EQ(knob.count_at(t), 2400 * t / kSecond) << t;
  }
}

}  // namespace
}  // namespace stepdance::sim
