// Shared GoogleTest fixture for the host Arduino API: a fresh manual board, engine and API state.
#pragma once

#include <gtest/gtest.h>

#include <stdint.h>

#include <string>

#include "Arduino.h"
#include "arduino_manual.hpp"
#include "hal_manual.hpp"
#include "support/engine_fixture.hpp"

namespace stepdance::test_support {

/// Everything global back to power-on: the manual board (time starts at start_us), the engine,
/// the fault record, the manual serial ports and delay statistics, and the Arduino API's state.
inline void reset_arduino_board(uint32_t start_us = 0) {
  reset_global_state(start_us);
  arduino_manual::reset();
  arduino::reset_state();
}

/// Derive tests of the Arduino API from this: each test starts and ends on a clean board.
class ArduinoFixture : public ::testing::Test {
 protected:
  void SetUp() override { reset_arduino_board(); }
  void TearDown() override { reset_arduino_board(); }
};

/// A Print that keeps what is written, to check formatting byte for byte.
class CapturePrint : public Print {
 public:
  size_t write(uint8_t byte) override {
    text += static_cast<char>(byte);
    return 1;
  }
  using Print::write;
  /// Returns the text written so far and starts afresh.
  std::string take() {
    std::string out;
    out.swap(text);
    return out;
  }
  std::string text;
};

}  // namespace stepdance::test_support
