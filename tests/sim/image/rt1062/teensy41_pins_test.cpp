// The simulator's Teensy 4.1 pinout against our backend's pin table (every pin the backend
// knows, which is every pin a board of ours can use) and against PJRC's core_pins.h facts.
#define ARDUINO_TEENSY41 1
#include "backend_pins_view.hpp"

#include <gtest/gtest.h>

#include "image/rt1062/pads.hpp"
#include "image/rt1062/teensy_pins.hpp"

namespace stepdance::sim::image::rt1062 {
namespace {

constexpr auto kBackend = testing::backend_pins();

TEST(Teensy41Pins, EveryBackendPinHasTheSamePadPortAndBit) {
  ASSERT_EQ(highest_pin(TeensyModel::kTeensy41), 54);
  for (uint8_t pin = 0; pin <= testing::kBackendMaxPin; ++pin) {
    const int pad = teensy_pin_pad(TeensyModel::kTeensy41, pin);
    ASSERT_GE(pad, 0) << "pin " << int(pin);
    EXPECT_EQ(pad_mux_offset(pad), kBackend[pin].mux) << "pin " << int(pin) << " " << pad_name(pad);
    EXPECT_EQ(pad_gpio(pad).port, kBackend[pin].port) << "pin " << int(pin) << " " << pad_name(pad);
    EXPECT_EQ(pad_gpio(pad).bit, kBackend[pin].bit) << "pin " << int(pin) << " " << pad_name(pad);
    EXPECT_EQ(pad_teensy_pin(TeensyModel::kTeensy41, pad), pin);
  }
}

TEST(Teensy41Pins, AgreesWithPjrcCorePins) {
  // core_pins.h (1.59): CORE_PIN13_CONFIG = GPIO_B0_03, GPIO7 bit 3; CORE_PIN0 = GPIO_AD_B0_03,
  // GPIO6 bit 3; CORE_PIN29 = GPIO_EMC_31, GPIO9 bit 31; CORE_PIN28 = GPIO_EMC_32, GPIO8 bit 18.
  const TeensyModel m = TeensyModel::kTeensy41;
  EXPECT_STREQ(pad_name(teensy_pin_pad(m, 13)), "GPIO_B0_03");
  EXPECT_EQ(pad_gpio(teensy_pin_pad(m, 13)).port, 2);
  EXPECT_EQ(pad_gpio(teensy_pin_pad(m, 13)).bit, 3);
  EXPECT_STREQ(pad_name(teensy_pin_pad(m, 0)), "GPIO_AD_B0_03");
  EXPECT_EQ(pad_gpio(teensy_pin_pad(m, 29)).port, 4);
  EXPECT_EQ(pad_gpio(teensy_pin_pad(m, 29)).bit, 31);
  EXPECT_EQ(pad_gpio(teensy_pin_pad(m, 28)).port, 3);
  EXPECT_EQ(pad_gpio(teensy_pin_pad(m, 28)).bit, 18);
  EXPECT_EQ(teensy_pin_pad(m, 54 + 1), -1);
}

}  // namespace
}  // namespace stepdance::sim::image::rt1062

namespace stepdance::sim::image::rt1062 {
namespace {

TEST(Teensy41Pins, MemoryAndSdPadsBeyondTheBackendsTable) {
  // core_pins.h (1.59, Teensy 4.1): pins 42..47 = GPIO_SD_B0_03,02,01,00,05,04 (GPIO8 15..12,17,16);
  // 48..54 = GPIO_EMC_24,27,28,22,26,25,29 (GPIO9 bits alike).
  const TeensyModel m = TeensyModel::kTeensy41;
  EXPECT_STREQ(pad_name(teensy_pin_pad(m, 42)), "GPIO_SD_B0_03");
  EXPECT_EQ(pad_gpio(teensy_pin_pad(m, 42)).bit, 15);
  EXPECT_EQ(pad_gpio(teensy_pin_pad(m, 46)).bit, 17);
  EXPECT_STREQ(pad_name(teensy_pin_pad(m, 48)), "GPIO_EMC_24");
  EXPECT_STREQ(pad_name(teensy_pin_pad(m, 54)), "GPIO_EMC_29");
  EXPECT_EQ(pad_gpio(teensy_pin_pad(m, 51)).port, 4);
  EXPECT_EQ(pad_gpio(teensy_pin_pad(m, 51)).bit, 22);
}

TEST(Pads, AdcInputsMatchTeensyduinosPinToChannel) {
  // analog.c (1.59) pin_to_channel: pin 14 (AD_B1_02) = ADC1 ch 7; pin 24 (AD_B0_12) = ADC1 ch 1;
  // pin 26 (AD_B1_14) = ADC2 ch 3 only; pin 38 (AD_B1_12) = ADC2 ch 1; pin 21 (AD_B1_11) = ch 0.
  const TeensyModel m = TeensyModel::kTeensy41;
  EXPECT_EQ(adc_input_pad(0, 7), teensy_pin_pad(m, 14));
  EXPECT_EQ(adc_input_pad(1, 7), teensy_pin_pad(m, 14));
  EXPECT_EQ(adc_input_pad(0, 1), teensy_pin_pad(m, 24));
  EXPECT_EQ(adc_input_pad(1, 3), teensy_pin_pad(m, 26));
  EXPECT_EQ(adc_input_pad(1, 1), teensy_pin_pad(m, 38));
  EXPECT_EQ(adc_input_pad(0, 0), teensy_pin_pad(m, 21));
  EXPECT_EQ(adc_input_pad(0, 9), teensy_pin_pad(m, 40));
  EXPECT_EQ(adc_input_pad(0, 16), -1);
}

}  // namespace
}  // namespace stepdance::sim::image::rt1062
