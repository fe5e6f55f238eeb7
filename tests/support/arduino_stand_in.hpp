// The few Arduino names an example sketch uses, for compiling sketches into host unit tests.
// (The simulator has the full host Arduino API; this stand-in only lets a test include a sketch.)
#pragma once

#include <cstdint>
#include <string>

#include "stepdance/io/button.hpp"

constexpr uint8_t INPUT = stepdance::arduino_pin_mode::kInput;
constexpr uint8_t INPUT_PULLUP = stepdance::arduino_pin_mode::kInputPullup;
constexpr uint8_t INPUT_PULLDOWN = stepdance::arduino_pin_mode::kInputPulldown;

/// Collects what a sketch prints, so a test can read it.
struct SerialStandIn {
  std::string printed;
  template <typename T>
  void print(const T& value) { printed += std::to_string(value); }
  void print(const char* text) { printed += text; }
  template <typename T>
  void println(const T& value) {
    print(value);
    printed += "\r\n";
  }
};
inline SerialStandIn Serial;
