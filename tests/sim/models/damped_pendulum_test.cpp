// Damped pendulum on an encoder: held, released, swinging and decaying, counted by edges.
#include "models/damped_pendulum.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace stepdance::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;

PendulumSettings forty_degrees() {
  PendulumSettings settings;
  settings.pulses_per_revolution = 600;  // 2400 counts a turn
  settings.amplitude_deg = 40;           // 266.67 counts from vertical
  settings.period_s = 2;
  settings.decay_s = 30;
  settings.release = from_seconds(1);
  return settings;
}

TEST(DampedPendulum, CountsZeroWhereItIsHeldUntilReleased) {
  const DampedPendulum pendulum(forty_degrees());
  EXPECT_EQ(pendulum.count_at(0), 0);
  EXPECT_EQ(pendulum.count_at(from_seconds(1)), 0);
  EXPECT_NEAR(pendulum.angle_rad_at(from_seconds(0.5)), 40 * kPi / 180, 1e-12);
}

// Hand calculation: 40° = 266.667 counts, floor 266 at power-on.
//  t₀ + T/2: −266.667·e^(−1/30) = −257.924 → floor −258 → count −524.
//  t₀ + T:    266.667·e^(−2/30) =  249.469 → floor 249  → count −17.
TEST(DampedPendulum, SwingsToTheOtherSideAndBackSmaller) {
  const DampedPendulum pendulum(forty_degrees());
  EXPECT_EQ(pendulum.count_at(from_seconds(2)), -524);
  EXPECT_EQ(pendulum.count_at(from_seconds(3)), -17);
  EXPECT_NEAR(pendulum.angle_rad_at(from_seconds(1.5)), 0.0, 1e-12);  // a quarter swing: vertical
}

TEST(DampedPendulum, DecaysWithItsTimeConstant) {
  const DampedPendulum pendulum(forty_degrees());
  // After 30 whole periods (60 s = 2τ) the swing is e^(−2) of the release angle.
  const double expected = 40 * kPi / 180 * std::exp(-2.0);
  EXPECT_NEAR(pendulum.angle_rad_at(from_seconds(61)), expected, 1e-9);
}

}  // namespace
}  // namespace stepdance::sim
