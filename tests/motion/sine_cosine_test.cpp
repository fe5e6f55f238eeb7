// sine_cosine: one argument reduction for both, checked against the C library's own sin and cos.
#include <gtest/gtest.h>
#include <math.h>

#include <random>

#include "stepdance/motion/sine_cosine.hpp"

namespace stepdance {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kHalfPi = kPi / 2;

// The library reduces each argument itself (with far more bits of π); agreement within a few
// parts in 10¹⁵ of the angle's size shows the quarter-turn reduction and the rotation are right.
void expect_matches_library(double theta) {
  const SineCosine both = sine_cosine(theta);
  const double tolerance = 4e-16 * (1.0 + fabs(theta));
  EXPECT_NEAR(both.sine, sin(theta), tolerance) << "theta " << theta;
  EXPECT_NEAR(both.cosine, cos(theta), tolerance) << "theta " << theta;
}

TEST(SineCosine, EveryQuadrantAndBothSignsMatchTheLibrary) {
  for (int quarter = -12; quarter <= 12; ++quarter) {
    for (double offset : {-0.7, -0.3, 0.0, 0.2, 0.78}) expect_matches_library(quarter * kHalfPi + offset);
  }
}

TEST(SineCosine, RandomAnglesUpToHoursOfTurningMatchTheLibrary) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> angle(-2.0e5, 2.0e5);  // 20 hours at 2.75 rad/s
  for (int i = 0; i < 20000; ++i) expect_matches_library(angle(random));
}

TEST(SineCosine, HugeAndNonFiniteAnglesFallBackToTheLibrary) {
  expect_matches_library(3.0e6);
  expect_matches_library(-1.0e12);
  EXPECT_TRUE(isnan(sine_cosine(NAN).sine));
  EXPECT_TRUE(isnan(sine_cosine(INFINITY).cosine));
}

TEST(SineCosine, KnownValues) {
  const SineCosine sixth = sine_cosine(kPi / 6);
  EXPECT_NEAR(sixth.sine, 0.5, 3e-16);              // the angle itself is rounded to a double
  EXPECT_NEAR(sixth.cosine, sqrt(3.0) / 2, 3e-16);  // the angle itself is rounded to a double
  const SineCosine back = sine_cosine(-3 * (kPi / 4));
  EXPECT_NEAR(back.sine, -sqrt(0.5), 3e-16);    // the angle itself is rounded to a double
  EXPECT_NEAR(back.cosine, -sqrt(0.5), 3e-16);  // the angle itself is rounded to a double
}

}  // namespace
}  // namespace stepdance
