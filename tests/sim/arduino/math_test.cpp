// Arduino math helpers: constants, min/max/constrain, integer and floating map(), random().
#include <gtest/gtest.h>

#include <type_traits>

#include "arduino_fixture.hpp"

namespace {

class MathTest : public stepdance::test_support::ArduinoFixture {};

TEST_F(MathTest, Constants) {
  EXPECT_DOUBLE_EQ(PI, 3.141592653589793);
  EXPECT_DOUBLE_EQ(TWO_PI, 2 * 3.141592653589793);
  EXPECT_DOUBLE_EQ(HALF_PI, 3.141592653589793 / 2);
  EXPECT_DOUBLE_EQ(radians(180), PI);
  EXPECT_DOUBLE_EQ(degrees(HALF_PI), 90.0);
}

TEST_F(MathTest, MinMaxConstrainInTheCommonType) {
  EXPECT_EQ(min(3, 7), 3);
  EXPECT_EQ(max(3, 7), 7);
  EXPECT_EQ(min(-1, 2), -1);
  EXPECT_DOUBLE_EQ(max(3, 7.5), 7.5);
  static_assert(std::is_same_v<decltype(max(3, 7.5)), double>);
  EXPECT_EQ(constrain(15, 0, 10), 10);
  EXPECT_EQ(constrain(-3, 0, 10), 0);
  EXPECT_EQ(constrain(4, 0, 10), 4);
  EXPECT_DOUBLE_EQ(constrain(2.5, 0.0, 1.0), 1.0);
  EXPECT_EQ(sq(-4), 16);
  EXPECT_DOUBLE_EQ(sq(1.5), 2.25);
  static_assert(min(2, 5) == 2, "usable in constant expressions");
}

TEST_F(MathTest, IntegerMapTruncatesTowardZero) {
  EXPECT_EQ(map(512, 0, 1023, 0, 255), 127);  // 130 560 / 1023 = 127.6
  EXPECT_EQ(map(1023, 0, 1023, 0, 255), 255);
  EXPECT_EQ(map(-5, 0, 10, 0, 100), -50);  // no clamping
  EXPECT_EQ(map(3, 0, 10, 100, 0), 70);    // reversed output range
  EXPECT_EQ(map(7, 0, 3, 0, 10), 23);      // 70 / 3 = 23.3
  EXPECT_EQ(map(-1, 0, 3, 0, 10), -3);     // −10 / 3 = −3.3, truncated toward zero
  EXPECT_EQ(map(5, 2, 2, 40, 80), 40);     // empty input range: out_min
  static_assert(std::is_same_v<decltype(map(1, 0, 2, 0, 4)), long>);
}

TEST_F(MathTest, FloatingMapKeepsTheFraction) {
  EXPECT_DOUBLE_EQ(map(0.5, 0.0, 1.0, 0.0, 10.0), 5.0);
  EXPECT_FLOAT_EQ(map(512, 0, 1023, 0.0f, 10.0f), 5120.0f / 1023.0f);
  static_assert(std::is_same_v<decltype(map(512, 0, 1023, 0.0f, 10.0f)), float>);
  EXPECT_DOUBLE_EQ(map(1.0, 1.0, 1.0, -2.0, 2.0), -2.0);
}

TEST_F(MathTest, RandomIsRepeatableAndInRange) {
  randomSeed(42);
  long first[8];
  for (long& value : first) {
    value = random(100);
    EXPECT_GE(value, 0);
    EXPECT_LT(value, 100);
  }
  randomSeed(42);
  for (long value : first) EXPECT_EQ(random(100), value);
  for (int i = 0; i < 100; ++i) {
    const long value = random(-5, 5);
    EXPECT_GE(value, -5);
    EXPECT_LT(value, 5);
  }
  EXPECT_EQ(random(0), 0);
  EXPECT_EQ(random(-3), 0);
  EXPECT_EQ(random(7, 7), 7);
  EXPECT_EQ(random(9, 2), 9);
}

TEST_F(MathTest, RandomStartsAsIfSeededWithOne) {
  const long after_reset = random(1000000);
  randomSeed(1);
  EXPECT_EQ(random(1000000), after_reset);
}

}  // namespace
