// Teensy's elapsedMillis / elapsedMicros on the host: variables that count up by themselves.
#pragma once

#include <stdint.h>

#include "arduino_time.h"

/// Milliseconds since the variable was created or last assigned; assigning sets its current
/// reading (`elapsed = 0` restarts it). Wraps like millis(). Context: loop.
class elapsedMillis {
 public:
  elapsedMillis() : start_(millis()) {}
  elapsedMillis(uint32_t value) : start_(millis() - value) {}  // NOLINT: implicit, as on a Teensy
  operator uint32_t() const { return millis() - start_; }
  elapsedMillis& operator=(uint32_t value) {
    start_ = millis() - value;
    return *this;
  }
  elapsedMillis& operator+=(uint32_t value) {
    start_ -= value;
    return *this;
  }
  elapsedMillis& operator-=(uint32_t value) {
    start_ += value;
    return *this;
  }

 private:
  uint32_t start_;
};

/// As elapsedMillis, in microseconds (wraps like micros(), every 71.6 minutes). Context: any.
class elapsedMicros {
 public:
  elapsedMicros() : start_(micros()) {}
  elapsedMicros(uint32_t value) : start_(micros() - value) {}  // NOLINT: implicit, as on a Teensy
  operator uint32_t() const { return micros() - start_; }
  elapsedMicros& operator=(uint32_t value) {
    start_ = micros() - value;
    return *this;
  }
  elapsedMicros& operator+=(uint32_t value) {
    start_ -= value;
    return *this;
  }
  elapsedMicros& operator-=(uint32_t value) {
    start_ += value;
    return *this;
  }

 private:
  uint32_t start_;
};
