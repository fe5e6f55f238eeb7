// The simulator's Teensy 4.0 pinout against our backend's pin table (every pin the backend
// knows, which is every pin a board of ours can use) and against PJRC's core_pins.h facts.
#define ARDUINO_TEENSY40 1
#include "backend_pins_view.hpp"

#include <gtest/gtest.h>

#include "image/rt1062/pads.hpp"
#include "image/rt1062/teensy_pins.hpp"

namespace stepdance::sim::image::rt1062 {
namespace {

constexpr auto kBackend = testing::backend_pins();

TEST(Teensy40Pins, EveryBackendPinHasTheSamePadPortAndBit) {
  ASSERT_EQ(highest_pin(TeensyModel::kTeensy40), 39);
  for (uint8_t pin = 0; pin <= testing::kBackendMaxPin; ++pin) {
    const int pad = teensy_pin_pad(TeensyModel::kTeensy40, pin);
    ASSERT_GE(pad, 0) << "pin " << int(pin);
    EXPECT_EQ(pad_mux_offset(pad), kBackend[pin].mux) << "pin " << int(pin) << " " << pad_name(pad);
    EXPECT_EQ(pad_gpio(pad).port, kBackend[pin].port) << "pin " << int(pin) << " " << pad_name(pad);
    EXPECT_EQ(pad_gpio(pad).bit, kBackend[pin].bit) << "pin " << int(pin) << " " << pad_name(pad);
    EXPECT_EQ(pad_teensy_pin(TeensyModel::kTeensy40, pad), pin);
  }
}

TEST(Teensy40Pins, AgreesWithPjrcCorePins) {
  // core_pins.h (1.59): CORE_PIN13_CONFIG = GPIO_B0_03, GPIO7 bit 3; CORE_PIN0 = GPIO_AD_B0_03,
  // GPIO6 bit 3; CORE_PIN29 = GPIO_EMC_31, GPIO9 bit 31; CORE_PIN28 = GPIO_EMC_32, GPIO8 bit 18.
  const TeensyModel m = TeensyModel::kTeensy40;
  EXPECT_STREQ(pad_name(teensy_pin_pad(m, 13)), "GPIO_B0_03");
  EXPECT_EQ(pad_gpio(teensy_pin_pad(m, 13)).port, 2);
  EXPECT_EQ(pad_gpio(teensy_pin_pad(m, 13)).bit, 3);
  EXPECT_STREQ(pad_name(teensy_pin_pad(m, 0)), "GPIO_AD_B0_03");
  EXPECT_EQ(pad_gpio(teensy_pin_pad(m, 29)).port, 4);
  EXPECT_EQ(pad_gpio(teensy_pin_pad(m, 29)).bit, 31);
  EXPECT_EQ(pad_gpio(teensy_pin_pad(m, 28)).port, 3);
  EXPECT_EQ(pad_gpio(teensy_pin_pad(m, 28)).bit, 18);
  EXPECT_EQ(teensy_pin_pad(m, 39 + 1), -1);
}

}  // namespace
}  // namespace stepdance::sim::image::rt1062
