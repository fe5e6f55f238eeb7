// servo_pulse_width_test.cpp: pulse width and OCR1B from the step position, for both shipped builds.
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>

#include "servo_pulse.h"
#include "servo_test_settings.h"

namespace {

using servo_test::settings_180deg;
using servo_test::settings_90deg;

// Hand-derived: 1500 us midpoint + 40 us width offset.
constexpr std::uint16_t kNeutralWidthUs = 1540;

TEST(ServoPulseWidth, StartsAtNeutral) {
  const servo_pulse_settings settings = settings_90deg();
  EXPECT_EQ(kNeutralWidthUs, servo_pulse_width_us(&settings, 0));
  EXPECT_EQ(1539, servo_pulse_compare_for_width_us(servo_pulse_width_us(&settings, 0)));
}

TEST(ServoPulseWidth, OneMicrosecondPerStep) {
  const servo_pulse_settings settings = settings_90deg();
  EXPECT_EQ(1541, servo_pulse_width_us(&settings, 1));
  EXPECT_EQ(1539, servo_pulse_width_us(&settings, -1));
  EXPECT_EQ(1790, servo_pulse_width_us(&settings, 250));
  EXPECT_EQ(1290, servo_pulse_width_us(&settings, -250));
  for (std::int32_t steps = -500; steps < 500; ++steps) {
    ASSERT_EQ(servo_pulse_width_us(&settings, steps) + 1, servo_pulse_width_us(&settings, steps + 1))
        << "at " << steps << " steps";
  }
}

TEST(ServoPulseWidth, WindowOf90DegreeBuild) {
  const servo_pulse_settings settings = settings_90deg();
  EXPECT_EQ(2040, servo_pulse_width_us(&settings, 500));
  EXPECT_EQ(1040, servo_pulse_width_us(&settings, -500));
  EXPECT_EQ(2039, servo_pulse_compare_for_width_us(servo_pulse_width_us(&settings, 500)));
  EXPECT_EQ(1039, servo_pulse_compare_for_width_us(servo_pulse_width_us(&settings, -500)));
}

TEST(ServoPulseWidth, WindowOf180DegreeBuild) {
  const servo_pulse_settings settings = settings_180deg();
  EXPECT_EQ(kNeutralWidthUs, servo_pulse_width_us(&settings, 0));
  EXPECT_EQ(2290, servo_pulse_width_us(&settings, 750));
  EXPECT_EQ(790, servo_pulse_width_us(&settings, -750));
  EXPECT_EQ(2040, servo_pulse_width_us(&settings, 500));
  EXPECT_EQ(1040, servo_pulse_width_us(&settings, -500));
}

TEST(ServoPulseWidth, ClampsBeyondTheWindowOf90DegreeBuild) {
  const servo_pulse_settings settings = settings_90deg();
  EXPECT_EQ(2040, servo_pulse_width_us(&settings, 501));
  EXPECT_EQ(2040, servo_pulse_width_us(&settings, 600));
  EXPECT_EQ(2040, servo_pulse_width_us(&settings, std::numeric_limits<std::int32_t>::max()));
  EXPECT_EQ(1040, servo_pulse_width_us(&settings, -501));
  EXPECT_EQ(1040, servo_pulse_width_us(&settings, -600));
  EXPECT_EQ(1040, servo_pulse_width_us(&settings, std::numeric_limits<std::int32_t>::min()));
}

TEST(ServoPulseWidth, ClampsBeyondTheWindowOf180DegreeBuild) {
  const servo_pulse_settings settings = settings_180deg();
  EXPECT_EQ(2290, servo_pulse_width_us(&settings, 751));
  EXPECT_EQ(2290, servo_pulse_width_us(&settings, 100000));
  EXPECT_EQ(790, servo_pulse_width_us(&settings, -751));
  EXPECT_EQ(790, servo_pulse_width_us(&settings, -100000));
}

// The position keeps counting past a limit; coming back from 600 to 450 moves the servo at once.
TEST(ServoPulseWidth, ReturnsFromBeyondTheWindowWithoutLag) {
  const servo_pulse_settings settings = settings_90deg();
  EXPECT_EQ(2040, servo_pulse_width_us(&settings, 600));
  EXPECT_EQ(1990, servo_pulse_width_us(&settings, 450));
}

TEST(ServoPulseClamp, LimitsStepsToTheWindow) {
  const servo_pulse_settings settings = settings_90deg();
  EXPECT_EQ(0, servo_pulse_clamp_steps(&settings, 0));
  EXPECT_EQ(500, servo_pulse_clamp_steps(&settings, 500));
  EXPECT_EQ(500, servo_pulse_clamp_steps(&settings, 501));
  EXPECT_EQ(-500, servo_pulse_clamp_steps(&settings, -500));
  EXPECT_EQ(-500, servo_pulse_clamp_steps(&settings, -501));
}

}  // namespace
