// pinMode, digitalRead/Write and analogRead over the manual backend's pins and ADC.
#include <gtest/gtest.h>

#include "arduino_fixture.hpp"

namespace {

using stepdance::arduino_manual::delay_calls;
using stepdance::hal::PinMode;
using stepdance::hal_manual::pin_level;
using stepdance::hal_manual::pin_mode;
using stepdance::hal_manual::set_adc;
using stepdance::hal_manual::set_pin;

class PinsTest : public stepdance::test_support::ArduinoFixture {};

TEST_F(PinsTest, ModeNumbersMatchTheTeensyCore) {
  EXPECT_EQ(INPUT, 0);
  EXPECT_EQ(OUTPUT, 1);
  EXPECT_EQ(INPUT_PULLUP, 2);
  EXPECT_EQ(INPUT_PULLDOWN, 3);
  EXPECT_EQ(HIGH, 1);
  EXPECT_EQ(LOW, 0);
  EXPECT_EQ(A0, 14);
  EXPECT_EQ(A14, 38);
}

TEST_F(PinsTest, PinModeConfiguresTheHalPin) {
  pinMode(5, OUTPUT);
  EXPECT_EQ(pin_mode(5), PinMode::kOutput);
  pinMode(6, INPUT_PULLUP);
  EXPECT_EQ(pin_mode(6), PinMode::kInputPullup);
  pinMode(7, INPUT_PULLDOWN);
  EXPECT_EQ(pin_mode(7), PinMode::kInputPulldown);
  pinMode(5, INPUT);
  EXPECT_EQ(pin_mode(5), PinMode::kInput);
  pinMode(5, OUTPUT);
  pinMode(5, 42);  // unknown modes are ignored
  EXPECT_EQ(pin_mode(5), PinMode::kOutput);
}

TEST_F(PinsTest, DigitalWriteDrivesAndDigitalReadReads) {
  pinMode(5, OUTPUT);
  digitalWrite(5, HIGH);
  EXPECT_TRUE(pin_level(5));
  digitalWrite(5, LOW);
  EXPECT_FALSE(pin_level(5));
  digitalWrite(5, 7);  // any non-zero value is HIGH
  EXPECT_TRUE(pin_level(5));
  EXPECT_EQ(digitalRead(5), HIGH);

  pinMode(6, INPUT_PULLUP);
  EXPECT_EQ(digitalRead(6), HIGH);  // the pull-up holds an open input high
  set_pin(6, false);
  EXPECT_EQ(digitalRead(6), LOW);
  pinMode(7, INPUT_PULLDOWN);
  EXPECT_EQ(digitalRead(7), LOW);
}

TEST_F(PinsTest, AnalogReadReturnsTheLatestConversion) {
  set_adc(24, 512);
  EXPECT_EQ(analogRead(24), 512);
  set_adc(24, 1023);
  EXPECT_EQ(analogRead(24), 1023);
  EXPECT_EQ(delay_calls(), 0u);  // the pin had converted already: no wait
}

TEST_F(PinsTest, AnalogReadResolutionScalesTheTenBitValue) {
  set_adc(24, 1023);
  analogReadResolution(12);
  EXPECT_EQ(analogRead(24), 4092);  // 1023 << 2
  analogReadResolution(8);
  EXPECT_EQ(analogRead(24), 255);  // 1023 >> 2
  analogReadResolution(0);         // clamped to 1 bit
  EXPECT_EQ(analogRead(24), 1);
  analogReadResolution(10);
  EXPECT_EQ(analogRead(24), 1023);
}

TEST_F(PinsTest, FirstReadOfANeverConvertedPinWaitsUpTo100Microseconds) {
  EXPECT_EQ(analogRead(25), 0);
  EXPECT_EQ(delay_calls(), 10u);  // ten 10 µs steps
  EXPECT_EQ(stepdance::hal::micros_now(), 100u);
  EXPECT_EQ(analogRead(25), 0);
  EXPECT_EQ(delay_calls(), 10u);  // started once, no second wait
}

TEST_F(PinsTest, AnalogReadOfAPinWithoutAnAdcIsZero) {
  EXPECT_EQ(analogRead(200), 0);  // the manual backend has pins 0..54
  EXPECT_EQ(delay_calls(), 0u);
}

}  // namespace
