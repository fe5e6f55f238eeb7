// Potentiometer: position schedule and 10-bit ADC readings.
#include <gtest/gtest.h>

#include "models/potentiometer.hpp"

namespace stepdance::sim {
namespace {

TEST(Potentiometer, ReadsRoundPositionTimes1023) {
  Potentiometer pot;
  EXPECT_DOUBLE_EQ(pot.position_at(0), 0.5);
  EXPECT_EQ(pot.adc_value_at(0), 512);  // 511.5 rounds up
  pot.set(1 * kSecond, 0.25);
  EXPECT_EQ(pot.adc_value_at(1 * kSecond - 1), 512);
  EXPECT_EQ(pot.adc_value_at(1 * kSecond), 256);  // 255.75
  pot.set(2 * kSecond, 1.0);
  EXPECT_EQ(pot.adc_value_at(2 * kSecond), 1023);
  pot.set(3 * kSecond, 0.001);
  EXPECT_EQ(pot.adc_value_at(3 * kSecond), 1);  // 1.023
}

TEST(Potentiometer, PositionsAreClampedAndTheLaterSettingOfAnInstantWins) {
  Potentiometer pot(2.0);
  EXPECT_EQ(pot.adc_value_at(0), 1023);
  pot.set(5 * kSecond, -1.0);
  pot.set(4 * kSecond, 0.1);
  pot.set(5 * kSecond, 0.2);
  EXPECT_EQ(pot.adc_value_at(4 * kSecond), 102);  // 102.3
  EXPECT_EQ(pot.adc_value_at(5 * kSecond), 205);  // 204.6
}

}  // namespace
}  // namespace stepdance::sim
