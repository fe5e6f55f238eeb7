// LimitSwitch: trip points on either side, read from a machine axis.
#include <gtest/gtest.h>

#include "models/cartesian_machine.hpp"
#include "models/limit_switch.hpp"

namespace stepdance::sim {
namespace {

TEST(LimitSwitch, BelowIsActiveAtOrUnderTheTripPoint) {
  const LimitSwitch home(MachineAxis::kX, 0.0);
  EXPECT_TRUE(home.active_at(-0.1));
  EXPECT_TRUE(home.active_at(0.0));
  EXPECT_FALSE(home.active_at(0.1));
}

TEST(LimitSwitch, AboveIsActiveAtOrOverTheTripPoint) {
  const LimitSwitch end(MachineAxis::kY, 300.0, LimitSide::kAbove);
  EXPECT_TRUE(end.active_at(300.0));
  EXPECT_TRUE(end.active_at(301.0));
  EXPECT_FALSE(end.active_at(299.9));
}

TEST(LimitSwitch, ReadsTheMachineAxisAtItsLastUpdate) {
  StepperDriverSettings enabled;
  enabled.enabled = true;
  StepperDriver x(enabled);
  StepperDriver z(enabled);
  CartesianDrivers drivers;
  drivers.x = &x;
  drivers.z = &z;
  CartesianMachine machine(drivers);
  const LimitSwitch x_home(MachineAxis::kX, -1.0);
  const LimitSwitch z_top(MachineAxis::kZ, 2.0, LimitSide::kAbove);
  machine.update(0);
  EXPECT_FALSE(x_home.active(machine));
  for (int i = 0; i < 80; ++i) x.on_step_rising(i, false);  // x = −1 mm
  for (int i = 0; i < 800; ++i) z.on_step_rising(i, true);  // z = 2 mm at 400 steps/mm
  EXPECT_FALSE(x_home.active(machine));                     // not updated yet
  machine.update(1000);
  EXPECT_TRUE(x_home.active(machine));
  EXPECT_TRUE(z_top.active(machine));
}

}  // namespace
}  // namespace stepdance::sim
