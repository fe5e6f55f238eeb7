// Shared fixture of the QWIIC driver tests: a clean board, both buses emptied, an I2C log.
#pragma once

#include <gtest/gtest.h>

#include <vector>

#include "hal_manual.hpp"
#include "i2c_manual.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/qwiic/qwiic_bus.hpp"
#include "support/engine_fixture.hpp"

namespace stepdance::test_support {

class QwiicFixture : public EngineFixture {
 protected:
  void SetUp() override {
    EngineFixture::SetUp();
    hal_manual::i2c_reset();
    qwiic_bus(QWIIC_0).clear();
    qwiic_bus(QWIIC_1).clear();
  }
  void TearDown() override {
    qwiic_bus(QWIIC_0).clear();
    qwiic_bus(QWIIC_1).clear();
    hal_manual::i2c_reset();
    EngineFixture::TearDown();
  }
  /// Runs `passes` loop passes, `us_between` µs apart.
  void loop_passes(int passes, uint32_t us_between = 200) {
    for (int i = 0; i < passes; ++i) {
      hal_manual::advance_us(us_between);
      dance_loop();
    }
  }
  /// The bytes written by transfer `index` of the log.
  static std::vector<uint8_t> written(size_t index) { return hal_manual::i2c_log().at(index).written; }
};

}  // namespace stepdance::test_support
