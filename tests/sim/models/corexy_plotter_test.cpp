// CorexyPlotter: pen position from motor steps, servo pen state, strokes and travel limits.
#include <gtest/gtest.h>

#include <cmath>

#include "models/corexy_plotter.hpp"

namespace stepdance::sim {
namespace {

constexpr SimTime kMs = kMillisecond;

/// Two enabled motors, the pen servo board and a plotter bound to them.
struct Plotter {
  explicit Plotter(const CorexySettings& settings = {}) : a(enabled()), b(enabled()), plotter(a, b, &servo, settings) {}
  static StepperDriverSettings enabled() {
    StepperDriverSettings settings;
    settings.enabled = true;
    return settings;
  }
  StepperDriver a;
  StepperDriver b;
  ServoBoard servo;
  CorexyPlotter plotter;
};

/// `count` steps in the AxiDraw's positive direction, which is DIR low (what a channel with
/// invert_output() sends for a positive target, and an EiBotBoard's positive motor step).
void steps(StepperDriver& driver, int count, SimTime time) {
  for (int i = 0; i < (count < 0 ? -count : count); ++i) driver.on_step_rising(time, count < 0);
}

void servo_steps(ServoBoard& servo, int count, SimTime time) {
  for (int i = 0; i < (count < 0 ? -count : count); ++i) servo.on_step_rising(time, count > 0);
}

// In the AxiDraw's positive motor steps (DIR low), the pen is at half their sum and difference.
TEST(CorexyPlotter, PenPositionIsHalfTheSumAndHalfTheDifference) {
  Plotter rig;
  steps(rig.a, 800, 0);
  steps(rig.b, 800, 0);
  rig.plotter.update(1);
  EXPECT_DOUBLE_EQ(rig.plotter.pen_position().x_mm, 10.0);  // (10 + 10) / 2
  EXPECT_DOUBLE_EQ(rig.plotter.pen_position().y_mm, 0.0);
  steps(rig.b, -1600, 2);  // a = 10 mm, b = −10 mm
  rig.plotter.update(3);
  EXPECT_DOUBLE_EQ(rig.plotter.pen_position().x_mm, 0.0);
  EXPECT_DOUBLE_EQ(rig.plotter.pen_position().y_mm, 10.0);
  steps(rig.a, 200, 4);   // a = 12.5 mm
  steps(rig.b, 1200, 4);  // b = 5 mm
  rig.plotter.update(5);
  EXPECT_DOUBLE_EQ(rig.plotter.a_mm(), -12.5);  // motor positions count DIR-high steps
  EXPECT_DOUBLE_EQ(rig.plotter.b_mm(), -5.0);
  EXPECT_DOUBLE_EQ(rig.plotter.pen_position().x_mm, 8.75);
  EXPECT_DOUBLE_EQ(rig.plotter.pen_position().y_mm, 3.75);
  EXPECT_EQ(rig.plotter.axis_mm(MachineAxis::kX), 8.75);
  EXPECT_EQ(rig.plotter.axis_mm(MachineAxis::kZ), std::nullopt);
}

// The real machine's convention (the original's sketches invert both channels so that +x runs
// from motor A to motor B and +y away from the long axis): a step with DIR high moves the pen the
// other way, so a non-inverted channel's positive target runs towards −x.
TEST(CorexyPlotter, DirHighOnBothMotorsMovesThePenTowardsMinusX) {
  Plotter rig;
  for (int i = 0; i < 800; ++i) {
    rig.a.on_step_rising(0, true);
    rig.b.on_step_rising(0, true);
  }
  rig.plotter.update(1);
  EXPECT_DOUBLE_EQ(rig.plotter.a_mm(), 10.0);
  EXPECT_DOUBLE_EQ(rig.plotter.pen_position().x_mm, -10.0);
  EXPECT_DOUBLE_EQ(rig.plotter.pen_position().y_mm, 0.0);
  for (int i = 0; i < 1600; ++i) rig.a.on_step_rising(2, false);  // a = −10 mm, b = 10 mm
  rig.plotter.update(3);
  EXPECT_DOUBLE_EQ(rig.plotter.pen_position().x_mm, 0.0);
  EXPECT_DOUBLE_EQ(rig.plotter.pen_position().y_mm, 10.0);
}

// A motor plugged in the other way round turns backwards for the same DIR, so only its half of
// the pen's motion flips: the same steps that moved the pen along +x now move it along +y.
TEST(CorexyPlotter, AReversedMotorFlipsItsContributionOnly) {
  StepperDriverSettings normal = Plotter::enabled();
  StepperDriverSettings reversed = Plotter::enabled();
  reversed.reversed = true;
  StepperDriver a(normal);
  StepperDriver b(reversed);
  CorexyPlotter plotter(a, b, nullptr);
  steps(a, 800, 0);
  steps(b, 800, 0);
  plotter.update(1);
  EXPECT_DOUBLE_EQ(b.position_steps(), 800.0);  // DIR high on a reversed motor
  EXPECT_DOUBLE_EQ(plotter.pen_position().x_mm, 0.0);
  EXPECT_DOUBLE_EQ(plotter.pen_position().y_mm, 10.0);
}

TEST(CorexyPlotter, PenIsDownWhileTheServoPulseIsBelowTheThreshold) {
  Plotter rig;
  rig.plotter.update(0);
  EXPECT_FALSE(rig.plotter.pen_down());   // 1540 µs
  servo_steps(rig.servo, -200, 1 * kMs);  // 1340 µs from pulse 2 (49.7 ms)
  rig.plotter.update(49 * kMs);
  EXPECT_FALSE(rig.plotter.pen_down());
  rig.plotter.update(50 * kMs);
  EXPECT_TRUE(rig.plotter.pen_down());
  servo_steps(rig.servo, 159, 51 * kMs);  // 1499 µs: still down
  rig.plotter.update(100 * kMs);
  EXPECT_TRUE(rig.plotter.pen_down());
  servo_steps(rig.servo, 1, 101 * kMs);  // 1500 µs: not below, so up (from pulse 6, 149.1 ms)
  rig.plotter.update(150 * kMs);
  EXPECT_FALSE(rig.plotter.pen_down());
}

TEST(CorexyPlotter, WithoutAServoThePenIsAlwaysDown) {
  StepperDriver a;
  StepperDriver b;
  CorexyPlotter plotter(a, b, nullptr);
  plotter.update(0);
  EXPECT_TRUE(plotter.pen_down());
}

TEST(CorexyPlotter, StrokesSplitOnPenUpAndDown) {
  CorexySettings settings;
  settings.trace.record_pen_up = true;
  Plotter rig(settings);
  CorexyPlotter& plotter = rig.plotter;
  plotter.update(0);                      // up at (0, 0)
  servo_steps(rig.servo, -200, 1 * kMs);  // down from pulse 2 (49.7 ms)
  plotter.update(50 * kMs);               // stroke 1 starts at (0, 0)
  steps(rig.a, 800, 51 * kMs);            // (5, 5)
  plotter.update(52 * kMs);
  servo_steps(rig.servo, 200, 53 * kMs);  // after sample 2: up from pulse 4 (99.4 ms)
  steps(rig.b, 800, 79 * kMs);            // (10, 0)
  plotter.update(80 * kMs);
  plotter.update(100 * kMs);      // up
  steps(rig.b, -800, 101 * kMs);  // (5, 5), pen up
  plotter.update(102 * kMs);
  servo_steps(rig.servo, -200, 103 * kMs);  // down from pulse 6 (149.1 ms)
  plotter.update(150 * kMs);                // stroke 2 starts at (5, 5)
  steps(rig.a, 800, 151 * kMs);             // (10, 10)
  plotter.update(152 * kMs);

  ASSERT_EQ(plotter.strokes().size(), 2u);
  EXPECT_EQ(plotter.strokes()[0], (Polyline{{0, 0}, {5, 5}, {10, 0}}));
  EXPECT_EQ(plotter.strokes()[1], (Polyline{{5, 5}, {10, 10}}));
  ASSERT_EQ(plotter.pen_up_moves().size(), 1u);  // the initial pen-up wait did not move
  EXPECT_EQ(plotter.pen_up_moves()[0], (Polyline{{10, 0}, {5, 5}}));
  const MachineStats stats = plotter.stats();
  EXPECT_EQ(stats.updates, 8u);
  EXPECT_EQ(stats.moves, 4u);
  EXPECT_EQ(stats.strokes, 2u);
  EXPECT_NEAR(stats.pen_down_mm, 15 * std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(stats.pen_up_mm, 5 * std::sqrt(2.0), 1e-12);
  EXPECT_EQ(stats.travel_excursions, 0u);
}

// Returning home one motor at a time (as an EBB steps them) may pass one microstep (1/80 mm of
// belt) outside the area: not an excursion. A tenth of a millimetre is.
TEST(CorexyPlotter, OneMicrostepOutsideIsNotAnExcursion) {
  Plotter rig;
  rig.plotter.update(0);
  steps(rig.a, -1, 1 * kMs);  // (−1/160, −1/160)
  rig.plotter.update(2 * kMs);
  steps(rig.b, -1, 3 * kMs);  // (−1/80, 0)
  rig.plotter.update(4 * kMs);
  steps(rig.a, 1, 5 * kMs);
  steps(rig.b, 1, 5 * kMs);
  rig.plotter.update(6 * kMs);
  EXPECT_EQ(rig.plotter.stats().travel_excursions, 0u);
  steps(rig.a, -8, 7 * kMs);
  steps(rig.b, -8, 7 * kMs);  // (−0.1, 0)
  rig.plotter.update(8 * kMs);
  EXPECT_EQ(rig.plotter.stats().travel_excursions, 1u);
  ASSERT_EQ(rig.plotter.travel()->excursions().size(), 1u);
  EXPECT_NEAR(rig.plotter.travel()->excursions()[0].overshoot_mm, 0.1, 1e-12);
}

TEST(CorexyPlotter, ReportsTravelOutsideTheArea) {
  Plotter rig;
  rig.plotter.update(0);
  steps(rig.b, 800, 1 * kMs);  // a = 0, b = 10 mm: (5, −5)
  rig.plotter.update(2 * kMs);
  steps(rig.b, -800, 3 * kMs);
  rig.plotter.update(4 * kMs);
  steps(rig.a, 24000, 5 * kMs);  // a = 300 mm, b = 0: (150, 150) inside
  rig.plotter.update(6 * kMs);
  steps(rig.b, -24000, 7 * kMs);  // b = −300 mm: (0, 300) is 82 mm past y = 218
  rig.plotter.update(8 * kMs);
  ASSERT_NE(rig.plotter.travel(), nullptr);
  const TravelMonitor& travel = *rig.plotter.travel();
  EXPECT_EQ(travel.excursion_count(), 2u);
  ASSERT_EQ(travel.excursions().size(), 2u);
  EXPECT_EQ(travel.excursions()[0].start, 2 * kMs);
  EXPECT_EQ(travel.excursions()[0].end, 4 * kMs);
  EXPECT_EQ(travel.excursions()[0].first, (PenPoint{5, -5}));
  EXPECT_DOUBLE_EQ(travel.excursions()[0].overshoot_mm, 5.0);
  EXPECT_DOUBLE_EQ(travel.excursions()[1].overshoot_mm, 82.0);
  EXPECT_EQ(rig.plotter.stats().travel_excursions, 2u);
}

}  // namespace
}  // namespace stepdance::sim
