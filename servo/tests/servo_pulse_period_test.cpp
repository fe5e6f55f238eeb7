// servo_pulse_period_test.cpp: the pulse period, Timer1 TOP/compare values and settings validation.
#include <gtest/gtest.h>

#include "servo_pulse.h"
#include "servo_test_settings.h"

namespace {

using servo_test::settings_180deg;
using servo_test::settings_90deg;

TEST(ServoSettings, DefaultsAreTheSeedValues) {
  EXPECT_EQ(24000, PULSE_PERIOD_US);
  EXPECT_EQ(850, PULSE_PERIOD_OFFSET);
  EXPECT_EQ(40, PULSE_WIDTH_OFFSET);
  EXPECT_EQ(500, SERVO_TOP_LIMIT_STEPS);
  EXPECT_EQ(-500, SERVO_BOTTOM_LIMIT_STEPS);
  EXPECT_EQ(1500, SERVO_MIDPOINT_PULSE_WIDTH_US);
}

// 24000 us + 850 us offset.
TEST(ServoPulsePeriod, IsPeriodPlusOffset) {
  const servo_pulse_settings settings = settings_90deg();
  EXPECT_EQ(24850, servo_pulse_period_us(&settings));
  const servo_pulse_settings wide = settings_180deg();
  EXPECT_EQ(24850, servo_pulse_period_us(&wide));
}

// Fast PWM counts 0..TOP, so a 24850-tick period needs ICR1 = 24849.
TEST(ServoPulsePeriod, TimerTopIsPeriodMinusOne) {
  EXPECT_EQ(24849, servo_pulse_top_for_period_us(24850));
  EXPECT_EQ(19999, servo_pulse_top_for_period_us(20000));
  EXPECT_EQ(65534, servo_pulse_top_for_period_us(65535));
}

// OC1B is high from BOTTOM through the tick where TCNT1 == OCR1B: OCR1B + 1 ticks.
TEST(ServoPulseCompare, IsWidthMinusOne) {
  EXPECT_EQ(1539, servo_pulse_compare_for_width_us(1540));
  EXPECT_EQ(0, servo_pulse_compare_for_width_us(1));
}

TEST(ServoSettingsValid, AcceptsBothShippedBuilds) {
  const servo_pulse_settings narrow = settings_90deg();
  const servo_pulse_settings wide = settings_180deg();
  EXPECT_TRUE(servo_pulse_settings_valid(&narrow));
  EXPECT_TRUE(servo_pulse_settings_valid(&wide));
}

TEST(ServoSettingsValid, RejectsAnInvertedWindow) {
  servo_pulse_settings settings = settings_90deg();
  settings.top_limit_steps = -10;
  settings.bottom_limit_steps = 10;
  EXPECT_FALSE(servo_pulse_settings_valid(&settings));
}

TEST(ServoSettingsValid, RejectsWidthsBelowOneMicrosecond) {
  servo_pulse_settings settings = settings_90deg();
  settings.bottom_limit_steps = -1539;  // narrowest width 1 us: still fine
  EXPECT_TRUE(servo_pulse_settings_valid(&settings));
  settings.bottom_limit_steps = -1540;  // narrowest width 0 us
  EXPECT_FALSE(servo_pulse_settings_valid(&settings));
}

TEST(ServoSettingsValid, RejectsPulsesReachingThePeriodEnd) {
  servo_pulse_settings settings = settings_90deg();
  settings.top_limit_steps = 24850 - 1540 - 1;  // widest width 24849 us: ends 1 us early
  EXPECT_TRUE(servo_pulse_settings_valid(&settings));
  settings.top_limit_steps = 24850 - 1540;  // widest width = the period
  EXPECT_FALSE(servo_pulse_settings_valid(&settings));
}

TEST(ServoSettingsValid, RejectsPeriodsTimer1CannotCount) {
  servo_pulse_settings settings = settings_90deg();
  settings.period_us = 65534;
  settings.period_offset_us = 1;  // 65535 us, the longest period
  EXPECT_TRUE(servo_pulse_settings_valid(&settings));
  settings.period_offset_us = 2;
  EXPECT_FALSE(servo_pulse_settings_valid(&settings));
}

}  // namespace
