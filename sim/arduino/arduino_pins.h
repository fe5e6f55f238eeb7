// Arduino pin functions and constants on the host: pinMode, digitalRead/Write, analogRead.
#pragma once

#include <stdint.h>

/// Pin levels.
constexpr uint8_t LOW = 0;
constexpr uint8_t HIGH = 1;

/// Pin modes, numbered as in the Teensy core (and stepdance::arduino_pin_mode, which
/// Button::begin(pin, mode) reads).
constexpr uint8_t INPUT = 0;
constexpr uint8_t OUTPUT = 1;
constexpr uint8_t INPUT_PULLUP = 2;
constexpr uint8_t INPUT_PULLDOWN = 3;

/// Teensy 4.1 pin numbers of the analog inputs (A0..A13 are the same on a Teensy 4.0).
constexpr uint8_t A0 = 14, A1 = 15, A2 = 16, A3 = 17, A4 = 18, A5 = 19, A6 = 20, A7 = 21, A8 = 22, A9 = 23, A10 = 24,
                  A11 = 25, A12 = 26, A13 = 27, A14 = 38, A15 = 39, A16 = 40, A17 = 41;
/// The Teensy's on-board LED.
constexpr uint8_t LED_BUILTIN = 13;

/// Configures a pin (INPUT, OUTPUT, INPUT_PULLUP, INPUT_PULLDOWN) through hal::gpio_mode.
/// Other mode numbers are ignored. Context: loop.
void pinMode(uint8_t pin, uint8_t mode);

/// Drives a pin high (any non-zero value) or LOW through hal::gpio_write. Context: any.
void digitalWrite(uint8_t pin, uint8_t value);

/// The pin's level, HIGH or LOW, from hal::gpio_read. Context: any.
int digitalRead(uint8_t pin);

/// The latest conversion of a pin, 0..1023 at the default 10-bit resolution. The first call
/// for a pin starts its background conversions (hal::adc_begin) and waits up to 100 µs of
/// board time for the first one. A pin without an ADC reads 0. Context: loop.
int analogRead(uint8_t pin);

/// Bits analogRead() returns (1..16, default 10). The HAL converts at 10 bits, so more bits
/// shift the value left and fewer shift it right, as the Teensy's wider ADC would look.
/// Context: loop.
void analogReadResolution(unsigned int bits);

/// Teensy's fast pin functions. On a Teensy they compile to one register access when the pin is
/// a constant; on the host they are digitalRead/digitalWrite. Context: any.
inline uint8_t digitalReadFast(uint8_t pin) { return static_cast<uint8_t>(digitalRead(pin)); }
inline void digitalWriteFast(uint8_t pin, uint8_t value) { digitalWrite(pin, value); }
