// PolarTurntable: the paper turns under the pen, so the pen draws at angle −θ on the paper.
#include <gtest/gtest.h>

#include <cmath>

#include "models/polar_turntable.hpp"

namespace stepdance::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;

StepperDriverSettings enabled() {
  StepperDriverSettings settings;
  settings.enabled = true;
  return settings;
}

void steps(StepperDriver& driver, int count) {
  for (int i = 0; i < (count < 0 ? -count : count); ++i) driver.on_step_rising(0, count > 0);
}

TEST(PolarTurntable, PenDrawsAtRadiusAndMinusTheTableAngle) {
  StepperDriver angle(enabled()), radius(enabled());
  PolarTurntable table(angle, radius, nullptr);  // 3200 steps/rev, 80 steps/mm
  steps(radius, 800);                            // r = 10 mm
  table.update(0);
  EXPECT_EQ(table.pen_position(), (PenPoint{10, 0}));
  steps(angle, 800);  // θ = π/2 counter-clockwise: the pen is now over the paper's −y side
  table.update(1);
  EXPECT_NEAR(table.angle_rad(), kPi / 2, 1e-15);
  EXPECT_NEAR(table.pen_position().x_mm, 0.0, 1e-12);
  EXPECT_NEAR(table.pen_position().y_mm, -10.0, 1e-12);
  steps(angle, -1200);  // θ = −π/4
  table.update(2);
  EXPECT_NEAR(table.pen_position().x_mm, 10 * std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(table.pen_position().y_mm, 10 * std::sqrt(0.5), 1e-12);
  EXPECT_EQ(table.axis_mm(MachineAxis::kX), 10.0);
  EXPECT_EQ(table.axis_mm(MachineAxis::kY), std::nullopt);
}

TEST(PolarTurntable, OneTableTurnAtFixedRadiusDrawsACircle) {
  StepperDriver angle(enabled()), radius(enabled());
  PolarTurntable table(angle, radius, nullptr);
  steps(radius, 1600);  // r = 20 mm
  for (int i = 0; i <= 3200; ++i) {
    if (i > 0) steps(angle, 1);
    table.update(i);
  }
  ASSERT_EQ(table.strokes().size(), 1u);
  const Polyline& circle = table.strokes()[0];
  EXPECT_GT(circle.size(), 20u);
  for (const PenPoint& p : circle) EXPECT_NEAR(std::hypot(p.x_mm, p.y_mm), 20.0, 1e-9);
  EXPECT_NEAR(circle.back().x_mm, 20.0, 1e-9);
  EXPECT_NEAR(circle.back().y_mm, 0.0, 1e-9);
  EXPECT_LT(circle[1].y_mm, 0.0);  // positive table angle: the line starts towards −y
  EXPECT_NEAR(table.stats().pen_down_mm, 2 * kPi * 20, 1e-3);
}

TEST(PolarTurntable, AServoLiftsThePen) {
  StepperDriver angle(enabled()), radius(enabled());
  ServoBoard servo;
  PolarTurntable table(angle, radius, &servo);
  table.update(0);
  EXPECT_FALSE(table.pen_down());
  for (int i = 0; i < 200; ++i) servo.on_step_rising(0, false);
  table.update(2 * servo.period());
  EXPECT_TRUE(table.pen_down());
}

}  // namespace
}  // namespace stepdance::sim
