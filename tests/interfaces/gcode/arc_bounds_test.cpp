// arc_bounds_mm against brute force: random arcs (every plane, both directions, partial and
// multi-turn sweeps, helical and with E) sampled at 20,001 points by the test's own parametric
// formula; the closed-form box must hold every sample and exceed them by no more than the
// sampling step can hide. Plus a few boxes worked out by hand.
#include <gtest/gtest.h>

#include <math.h>

#include <random>

#include "stepdance/interfaces/gcode/arc_geometry.hpp"

namespace stepdance::gcode {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// An arc from its centre, radius, start angle and signed sweep; the other axes move linearly.
Motion make_arc(int plane, double c0, double c1, double radius, double start_rad, double sweep_rad,
                const double (&other_start)[kAxisCount], const double (&other_end)[kAxisCount]) {
  static constexpr uint8_t kPlanes[3][3] = {
      {kAxisX, kAxisY, kAxisZ}, {kAxisZ, kAxisX, kAxisY}, {kAxisY, kAxisZ, kAxisX}};
  Motion arc;
  arc.kind = MotionKind::kArc;
  arc.plane_axis_0 = kPlanes[plane][0];
  arc.plane_axis_1 = kPlanes[plane][1];
  arc.plane_normal = kPlanes[plane][2];
  arc.center_0_mm = c0;
  arc.center_1_mm = c1;
  arc.radius_mm = radius;
  arc.sweep_rad = sweep_rad;
  for (int axis = 0; axis < kAxisCount; ++axis) {
    arc.start_mm[axis] = other_start[axis];
    arc.end_mm[axis] = other_end[axis];
  }
  arc.start_mm[arc.plane_axis_0] = c0 + radius * cos(start_rad);
  arc.start_mm[arc.plane_axis_1] = c1 + radius * sin(start_rad);
  arc.end_mm[arc.plane_axis_0] = c0 + radius * cos(start_rad + sweep_rad);
  arc.end_mm[arc.plane_axis_1] = c1 + radius * sin(start_rad + sweep_rad);
  return arc;
}

TEST(ArcBounds, RandomArcsAgainstDenseSampling) {
  std::mt19937_64 random(20261127);
  std::uniform_real_distribution<double> position(-100.0, 100.0);
  std::uniform_real_distribution<double> radius(0.01, 50.0);
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  constexpr int kSamples = 20000;
  for (int trial = 0; trial < 300; ++trial) {
    const int plane = trial % 3;
    // Sweeps from a sliver to three turns, half of them clockwise; some exactly a quarter.
    double sweep = trial % 7 == 0 ? kPi / 2.0 * (1 + trial % 4) : unit(random) * 6.0 * kPi;
    if (trial % 2 == 1) sweep = -sweep;
    double start[kAxisCount], end[kAxisCount];
    for (int axis = 0; axis < kAxisCount; ++axis) start[axis] = position(random), end[axis] = position(random);
    const double start_rad = trial % 5 == 0 ? kPi / 2.0 * (trial % 4) : angle(random);  // some on an extreme
    const double r = radius(random);
    const Motion arc = make_arc(plane, position(random), position(random), r, start_rad, sweep, start, end);
    double low[kAxisCount], high[kAxisCount];
    arc_bounds_mm(arc, low, high);

    double seen_low[kAxisCount], seen_high[kAxisCount];
    for (int axis = 0; axis < kAxisCount; ++axis) seen_low[axis] = HUGE_VAL, seen_high[axis] = -HUGE_VAL;
    for (int k = 0; k <= kSamples; ++k) {
      const double t = static_cast<double>(k) / kSamples;
      double point[kAxisCount];
      for (int axis = 0; axis < kAxisCount; ++axis) point[axis] = start[axis] + t * (end[axis] - start[axis]);
      point[arc.plane_axis_0] = arc.center_0_mm + r * cos(start_rad + t * sweep);
      point[arc.plane_axis_1] = arc.center_1_mm + r * sin(start_rad + t * sweep);
      for (int axis = 0; axis < kAxisCount; ++axis) {
        seen_low[axis] = fmin(seen_low[axis], point[axis]);
        seen_high[axis] = fmax(seen_high[axis], point[axis]);
      }
    }
    // Between two samples the circle bulges at most r(1 - cos(step / 2)) beyond them.
    const double hidden = r * (1.0 - cos(fabs(sweep) / kSamples / 2.0)) + 1e-9;
    for (int axis = 0; axis < kAxisCount; ++axis) {
      SCOPED_TRACE(testing::Message() << "trial " << trial << " axis " << axis << " sweep " << sweep);
      EXPECT_LE(low[axis], seen_low[axis] + 1e-9);
      EXPECT_GE(high[axis], seen_high[axis] - 1e-9);
      EXPECT_GE(low[axis], seen_low[axis] - hidden);
      EXPECT_LE(high[axis], seen_high[axis] + hidden);
    }
  }
}

TEST(ArcBounds, HandWorkedBoxes) {
  const double zero[kAxisCount] = {};
  double low[kAxisCount], high[kAxisCount];
  // A quarter from 0° to 90° counter-clockwise round (10, 20), r 5: just the two ends.
  arc_bounds_mm(make_arc(0, 10, 20, 5, 0.0, kPi / 2.0, zero, zero), low, high);
  EXPECT_NEAR(low[kAxisX], 10, 1e-12);
  EXPECT_NEAR(high[kAxisX], 15, 1e-12);
  EXPECT_NEAR(low[kAxisY], 20, 1e-12);
  EXPECT_NEAR(high[kAxisY], 25, 1e-12);
  // The same ends clockwise: three quarters, through 270° and 180° (X down to 5, Y down to 15).
  arc_bounds_mm(make_arc(0, 10, 20, 5, 0.0, -1.5 * kPi, zero, zero), low, high);
  EXPECT_NEAR(low[kAxisX], 5, 1e-12);
  EXPECT_NEAR(high[kAxisX], 15, 1e-12);
  EXPECT_NEAR(low[kAxisY], 15, 1e-12);
  EXPECT_NEAR(high[kAxisY], 25, 1e-12);
  // A 1,000-turn helix in the XZ plane (G18: Z first, X second) round Z 0, X 0, r 2, Y 0 → 7.
  double y_end[kAxisCount] = {};
  y_end[kAxisY] = 7.0;
  arc_bounds_mm(make_arc(1, 0, 0, 2, 0.3, -2000.0 * kPi, zero, y_end), low, high);
  EXPECT_NEAR(low[kAxisZ], -2, 1e-12);
  EXPECT_NEAR(high[kAxisZ], 2, 1e-12);
  EXPECT_NEAR(low[kAxisX], -2, 1e-12);
  EXPECT_NEAR(high[kAxisX], 2, 1e-12);
  EXPECT_EQ(low[kAxisY], 0.0);
  EXPECT_EQ(high[kAxisY], 7.0);
}

}  // namespace
}  // namespace stepdance::gcode
