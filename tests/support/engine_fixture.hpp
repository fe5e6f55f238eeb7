// Shared GoogleTest fixture: a fresh manual board, an empty stopped engine and no recorded fault.
#pragma once

#include <gtest/gtest.h>

#include <stdint.h>

#include "hal_manual.hpp"
#include "stepdance/core/engine.hpp"
#include "stepdance/core/fault.hpp"
#include "stepdance/core/frame_period.hpp"

namespace stepdance::test_support {

/// Returns every piece of global state the core keeps to power-on: the manual board (time starts
/// at start_us), the engine's registries, timers and statistics, and the fault record.
inline void reset_global_state(uint32_t start_us = 0) {
  stepdance::hal_manual::reset(start_us);
  stepdance::engine().clear();
  stepdance::set_frame_period_us(stepdance::kDefaultFramePeriodUs);
  stepdance::clear_fault();
  stepdance::clear_fault_subscribers();
}

/// Derive test fixtures from this to start and end every test on a clean board:
///   class ChannelTest : public stepdance::test_support::EngineFixture {};
/// Blocks declared inside a test body unregister themselves when they go out of scope.
class EngineFixture : public ::testing::Test {
 protected:
  void SetUp() override { reset_global_state(); }
  void TearDown() override { reset_global_state(); }
};

}  // namespace stepdance::test_support
