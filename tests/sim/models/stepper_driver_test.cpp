// StepperDriver: counting on STEP rising edges, enable handling, microsteps and rotation.
#include <gtest/gtest.h>

#include "models/stepper_driver.hpp"

namespace stepdance::sim {
namespace {

StepperDriver enabled_driver(int microsteps = 16) {
  StepperDriverSettings settings;
  settings.microsteps = microsteps;
  settings.enabled = true;
  return StepperDriver(settings);
}

TEST(StepperDriver, CountsOneMicrostepPerRisingEdgeSignedByDir) {
  StepperDriver driver = enabled_driver();
  for (int i = 0; i < 5; ++i) driver.on_step_rising(i * 40 * kMicrosecond, true);
  for (int i = 5; i < 7; ++i) driver.on_step_rising(i * 40 * kMicrosecond, false);
  EXPECT_EQ(driver.position_steps(), 3);
  EXPECT_EQ(driver.forward_steps(), 5u);
  EXPECT_EQ(driver.reverse_steps(), 2u);
  EXPECT_EQ(driver.ignored_steps(), 0u);
  EXPECT_EQ(driver.last_step_time(), 240 * kMicrosecond);
}

TEST(StepperDriver, AReversedMotorTurnsAgainstDirButTheDriverCountsAsWired) {
  StepperDriverSettings settings;
  settings.enabled = true;
  settings.reversed = true;
  StepperDriver driver(settings);
  for (int i = 0; i < 5; ++i) driver.on_step_rising(i * 40 * kMicrosecond, true);
  for (int i = 5; i < 7; ++i) driver.on_step_rising(i * 40 * kMicrosecond, false);
  EXPECT_TRUE(driver.reversed());
  EXPECT_EQ(driver.position_steps(), -3);
  EXPECT_DOUBLE_EQ(driver.revolutions(), -3.0 / 3200);
  EXPECT_EQ(driver.forward_steps(), 5u);  // DIR high, as the driver saw it
  EXPECT_EQ(driver.reverse_steps(), 2u);
}

TEST(StepperDriver, StartsDisabledByDefaultAndIgnoresSteps) {
  StepperDriver driver;
  EXPECT_FALSE(driver.enabled());
  driver.on_step_rising(0, true);
  driver.on_step_rising(1000, true);
  EXPECT_EQ(driver.position_steps(), 0);
  EXPECT_EQ(driver.ignored_steps(), 2u);
  EXPECT_EQ(driver.last_step_time(), -1);
}

TEST(StepperDriver, StepsWhileDisabledAreCountedSeparately) {
  StepperDriver driver = enabled_driver();
  driver.on_step_rising(0, true);
  driver.set_enabled(false);
  driver.on_step_rising(1000, true);
  driver.on_step_rising(2000, false);
  driver.set_enabled(true);
  driver.on_step_rising(3000, true);
  EXPECT_EQ(driver.position_steps(), 2);
  EXPECT_EQ(driver.ignored_steps(), 2u);
  EXPECT_EQ(driver.last_step_time(), 3000);
}

TEST(StepperDriver, RevolutionsAreStepsOverFullStepsTimesMicrosteps) {
  StepperDriver driver = enabled_driver(16);
  EXPECT_EQ(driver.steps_per_rev(), 3200);
  for (int i = 0; i < 800; ++i) driver.on_step_rising(i, true);
  EXPECT_DOUBLE_EQ(driver.revolutions(), 0.25);  // 800 / (200 × 16)
}

TEST(StepperDriver, MicrostepChangeKeepsTheAngleAlreadyTurned) {
  StepperDriver driver = enabled_driver(16);
  for (int i = 0; i < 1600; ++i) driver.on_step_rising(i, true);  // half a turn at 1/16
  ASSERT_TRUE(driver.set_microsteps(8));
  for (int i = 0; i < 400; ++i) driver.on_step_rising(2000 + i, true);  // a quarter turn at 1/8
  EXPECT_EQ(driver.position_steps(), 2000);
  EXPECT_DOUBLE_EQ(driver.revolutions(), 0.75);
}

TEST(StepperDriver, RejectsMicrostepSettingsTheJumpersCannotMake) {
  StepperDriver driver = enabled_driver(16);
  EXPECT_FALSE(driver.set_microsteps(3));
  EXPECT_FALSE(driver.set_microsteps(0));
  EXPECT_FALSE(driver.set_microsteps(128));
  EXPECT_EQ(driver.microsteps(), 16);
  EXPECT_TRUE(driver.set_microsteps(64));
  EXPECT_EQ(driver.steps_per_rev(), 12800);
  EXPECT_TRUE(StepperDriver::valid_microsteps(1));
}

}  // namespace
}  // namespace stepdance::sim
