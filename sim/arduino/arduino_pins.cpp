// Arduino pin functions over the HAL's GPIO and ADC primitives.
#include "arduino_pins.h"

#include <bitset>

#include "arduino_backend.hpp"
#include "arduino_state.hpp"
#include "stepdance/hal/hal.hpp"
#include "stepdance/io/arduino_pin_mode.hpp"

static_assert(INPUT == stepdance::arduino_pin_mode::kInput, "INPUT must match the core");
static_assert(INPUT_PULLUP == stepdance::arduino_pin_mode::kInputPullup, "INPUT_PULLUP must match");
static_assert(INPUT_PULLDOWN == stepdance::arduino_pin_mode::kInputPulldown, "INPUT_PULLDOWN must match");

namespace {

constexpr unsigned kHalAdcBits = 10;
constexpr unsigned kMaxAdcBits = 16;
// analogRead() waits for the first conversion of a newly started pin in these steps.
constexpr uint32_t kFirstConversionStepUs = 10;
constexpr uint32_t kFirstConversionSteps = 10;

std::bitset<256> adc_started;  // pins analogRead() has begun
unsigned adc_bits = kHalAdcBits;

bool start_adc(uint8_t pin) {
  if (adc_started[pin]) return true;
  if (stepdance::hal::adc_begin(pin) != stepdance::Status::kOk) return false;
  adc_started[pin] = true;
  // A pin that has never converted has no value yet: give the ADC a moment.
  for (uint32_t step = 0; step < kFirstConversionSteps; ++step) {
    if (stepdance::hal::adc_sample_count(pin) != 0) break;
    stepdance::arduino_backend::delay_us(kFirstConversionStepUs);
  }
  return true;
}

}  // namespace

namespace stepdance::arduino::internal {
void reset_pin_state() {
  adc_started.reset();
  adc_bits = kHalAdcBits;
}
}  // namespace stepdance::arduino::internal

void pinMode(uint8_t pin, uint8_t mode) {
  using stepdance::hal::PinMode;
  switch (mode) {
    case INPUT: stepdance::hal::gpio_mode(pin, PinMode::kInput); break;
    case OUTPUT: stepdance::hal::gpio_mode(pin, PinMode::kOutput); break;
    case INPUT_PULLUP: stepdance::hal::gpio_mode(pin, PinMode::kInputPullup); break;
    case INPUT_PULLDOWN: stepdance::hal::gpio_mode(pin, PinMode::kInputPulldown); break;
    default: break;
  }
}

void digitalWrite(uint8_t pin, uint8_t value) { stepdance::hal::gpio_write(pin, value != LOW); }

int digitalRead(uint8_t pin) { return stepdance::hal::gpio_read(pin) ? HIGH : LOW; }

int analogRead(uint8_t pin) {
  if (!start_adc(pin)) return 0;
  const unsigned value = stepdance::hal::adc_read(pin) & 0x3FFu;
  if (adc_bits >= kHalAdcBits) return static_cast<int>(value << (adc_bits - kHalAdcBits));
  return static_cast<int>(value >> (kHalAdcBits - adc_bits));
}

void analogReadResolution(unsigned int bits) {
  if (bits < 1) bits = 1;
  if (bits > kMaxAdcBits) bits = kMaxAdcBits;
  adc_bits = bits;
}
