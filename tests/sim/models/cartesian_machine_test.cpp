// CartesianMachine: per-axis steps per mm and the Z pen threshold.
#include <gtest/gtest.h>

#include "models/cartesian_machine.hpp"

namespace stepdance::sim {
namespace {

StepperDriverSettings enabled() {
  StepperDriverSettings settings;
  settings.enabled = true;
  return settings;
}

void steps(StepperDriver& driver, int count) {
  for (int i = 0; i < (count < 0 ? -count : count); ++i) driver.on_step_rising(0, count > 0);
}

TEST(CartesianMachine, AxesAreStepsOverStepsPerMm) {
  StepperDriver x(enabled()), y(enabled()), z(enabled()), e(enabled());
  CartesianMachine machine(CartesianDrivers{&x, &y, &z, &e});  // 80, 80, 400, 93 steps/mm
  steps(x, 800);
  steps(y, -1600);
  steps(z, 200);
  steps(e, 93);
  machine.update(1);
  EXPECT_EQ(machine.pen_position(), (PenPoint{10, -20}));
  EXPECT_DOUBLE_EQ(machine.z_mm(), 0.5);
  EXPECT_DOUBLE_EQ(machine.e_mm(), 1.0);
  EXPECT_EQ(machine.axis_mm(MachineAxis::kY), -20.0);
  EXPECT_EQ(machine.axis_mm(MachineAxis::kZ), 0.5);
}

TEST(CartesianMachine, PenIsDownAtOrBelowTheZThreshold) {
  StepperDriver x(enabled()), z(enabled());
  CartesianSettings settings;
  settings.pen_down_at_or_below_mm = 0.25;
  CartesianDrivers drivers;
  drivers.x = &x;
  drivers.z = &z;
  CartesianMachine machine(drivers, settings);
  steps(z, 101);  // 0.2525 mm
  machine.update(0);
  EXPECT_FALSE(machine.pen_down());
  steps(z, -1);  // 0.25 mm
  machine.update(1);
  EXPECT_TRUE(machine.pen_down());
  steps(x, 80);
  machine.update(2);
  steps(z, 100);
  machine.update(3);
  ASSERT_EQ(machine.strokes().size(), 1u);
  EXPECT_EQ(machine.strokes()[0], (Polyline{{0, 0}, {1, 0}}));
}

TEST(CartesianMachine, WithoutAZMotorThePenIsAlwaysDown) {
  StepperDriver x(enabled());
  CartesianDrivers drivers;
  drivers.x = &x;
  CartesianMachine machine(drivers);
  machine.update(0);
  EXPECT_TRUE(machine.pen_down());
  EXPECT_EQ(machine.travel(), nullptr);
}

TEST(CartesianMachine, AnOptionalTravelAreaIsMonitored) {
  StepperDriver x(enabled());
  CartesianSettings settings;
  settings.travel = TravelArea{0, 220, 0, 220};
  CartesianDrivers drivers;
  drivers.x = &x;
  CartesianMachine machine(drivers, settings);
  steps(x, -8);
  machine.update(0);
  ASSERT_NE(machine.travel(), nullptr);
  EXPECT_EQ(machine.travel()->excursion_count(), 1u);
  EXPECT_DOUBLE_EQ(machine.travel()->max_overshoot_mm(), 0.1);
}

// A printer draws while the extruder advances: it keeps drawing for extruding_hold after the
// last advance (extruder steps come less often than the axes'), and a retraction's refill is
// not a deposit.
TEST(CartesianMachine, APrinterDrawsWhileTheExtruderAdvances) {
  StepperDriver x(enabled()), e(enabled());
  CartesianSettings settings;
  settings.draws_while_extruding = true;
  settings.extruding_hold = 100 * kMillisecond;
  CartesianDrivers drivers;
  drivers.x = &x;
  drivers.e = &e;
  CartesianMachine machine(drivers, settings);
  machine.update(0);
  EXPECT_FALSE(machine.pen_down());  // nothing extruded yet
  steps(x, 80);                      // a travel move: 1 mm, no deposit
  machine.update(10 * kMillisecond);
  EXPECT_FALSE(machine.pen_down());
  steps(e, 1);
  machine.update(20 * kMillisecond);
  EXPECT_TRUE(machine.pen_down());
  steps(x, 80);                        // printing 1 mm...
  machine.update(120 * kMillisecond);  // ...100 ms after the extruder's last step
  EXPECT_TRUE(machine.pen_down());
  steps(x, 80);
  machine.update(121 * kMillisecond);  // past the hold: the nozzle is travelling
  EXPECT_FALSE(machine.pen_down());
  steps(e, -5);  // retract...
  machine.update(130 * kMillisecond);
  steps(e, 5);  // ...and refill to where it was: no deposit
  machine.update(140 * kMillisecond);
  EXPECT_FALSE(machine.pen_down());
  EXPECT_EQ(machine.axis_mm(MachineAxis::kE), 1.0 / 93);
  ASSERT_EQ(machine.strokes().size(), 1u);
  EXPECT_EQ(machine.strokes()[0], (Polyline{{1, 0}, {3, 0}}));
}

// A printer's shade is the filament deposited per mm of toolpath over each window: printing
// 10 mm with 0.05 mm of filament per mm (93 steps/mm: one E step every 1/(93 · 0.05) mm) reads
// 0.05 once a 5 mm window has passed, and the stroke takes it from its start.
TEST(CartesianMachine, APrinterShadesItsToolpathByFilamentPerMm) {
  StepperDriver x(enabled()), e(enabled());
  CartesianSettings settings;
  settings.draws_while_extruding = true;
  CartesianDrivers drivers;
  drivers.x = &x;
  drivers.e = &e;
  CartesianMachine machine(drivers, settings);
  EXPECT_STREQ(machine.shade_name(), "filament mm per toolpath mm");
  double deposited_mm = 0;
  int e_steps = 0;
  for (int i = 1; i <= 800; ++i) {  // 10 mm at 80 steps/mm
    steps(x, 1);
    deposited_mm += 0.05 / 80;
    while (e_steps + 1 <= deposited_mm * 93 + 1e-9) steps(e, 1), ++e_steps;
    machine.update(i * kMillisecond / 10);
  }
  ASSERT_EQ(machine.strokes().size(), 1u);
  ASSERT_EQ(machine.shade_marks().size(), 1u);
  ASSERT_FALSE(machine.shade_marks()[0].empty());
  for (const ShadeMark& mark : machine.shade_marks()[0]) EXPECT_NEAR(mark.shade, 0.05, 0.0025);
}

TEST(CartesianMachine, APlotterHasNoShade) {
  StepperDriver x(enabled());
  CartesianDrivers drivers;
  drivers.x = &x;
  CartesianMachine machine(drivers);
  steps(x, 800);
  machine.update(1);
  EXPECT_STREQ(machine.shade_name(), "");
  ASSERT_EQ(machine.shade_marks().size(), 1u);
  EXPECT_TRUE(machine.shade_marks()[0].empty());
}

}  // namespace
}  // namespace stepdance::sim
