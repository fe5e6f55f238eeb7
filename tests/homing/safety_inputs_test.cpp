// Unit tests of SafetyInputs: a limit alarm on closing (not while homing owns the switch, and
// not again while it stays closed), a fatal emergency stop, feed hold and cycle start.
#include <gtest/gtest.h>

#include "hal_manual.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/core/fault.hpp"
#include "stepdance/homing/homing.hpp"
#include "stepdance/homing/safety_inputs.hpp"
#include "stepdance/motion/channel.hpp"
#include "stepdance/motion/time_based_interpolator.hpp"
#include "support/engine_fixture.hpp"

namespace stepdance {
namespace {

constexpr uint8_t kLimitPin = 30;
constexpr uint8_t kStopPin = 31;
constexpr uint8_t kHoldPin = 32;
constexpr uint8_t kStartPin = 33;
constexpr uint32_t kFramesPerMs = 25;

class SafetyInputsTest : public test_support::EngineFixture {
 protected:
  void run_ms(uint32_t ms) {
    for (uint32_t i = 0; i < ms; ++i) {
      hal_manual::run_frames(kFramesPerMs);
      dance_loop();
    }
  }
  SafetyInputs safety;
};

TEST_F(SafetyInputsTest, ALimitClosingRaisesAnAlarmOnceAndClearingLetsTheAxisMoveAway) {
  ASSERT_EQ(safety.add_limit(kLimitPin), Status::kOk);
  ASSERT_EQ(safety.begin(), Status::kOk);
  ASSERT_EQ(dance_start(), Status::kOk);
  run_ms(20);
  EXPECT_FALSE(alarm_active());
  hal_manual::set_pin(kLimitPin, true);
  run_ms(3);  // shorter than the 5 ms debounce
  EXPECT_FALSE(alarm_active());
  run_ms(5);
  EXPECT_TRUE(alarm_active());
  FaultReport report;
  ASSERT_TRUE(recent_fault_report(0, report));
  EXPECT_EQ(report.reason, FaultReason::kLimitHit);
  clear_alarm();
  run_ms(50);  // still on the switch: no new alarm, the user may jog off it
  EXPECT_FALSE(alarm_active());
  EXPECT_EQ(safety.limit_hits(), 1u);
}

TEST_F(SafetyInputsTest, ALimitThatHomingOwnsRaisesNothingWhileHoming) {
  Channel channel;
  ASSERT_EQ(channel.begin(nullptr, SIGNAL_X), Status::kOk);
  Homing homing;
  ASSERT_EQ(homing.add_axis(kLimitPin, 0, HOMING_DIR_BWD, 10.0f, &channel.input_target_position), Status::kOk);
  ASSERT_EQ(homing.begin(), Status::kOk);
  ASSERT_EQ(safety.add_limit(kLimitPin), Status::kOk);
  safety.set_homing(&homing);
  ASSERT_EQ(safety.begin(), Status::kOk);
  ASSERT_EQ(dance_start(), Status::kOk);
  homing.start_homing_routine();
  hal_manual::set_pin(kLimitPin, true);
  run_ms(20);
  EXPECT_FALSE(alarm_active());
  EXPECT_EQ(safety.limit_hits(), 0u);
}

TEST_F(SafetyInputsTest, TheEmergencyStopIsFatal) {
  ASSERT_EQ(safety.add_emergency_stop(kStopPin), Status::kOk);  // normally closed: high = fine
  ASSERT_EQ(safety.begin(), Status::kOk);
  hal_manual::set_pin(kStopPin, true);  // the closed loop holds the pin at 3.3 V over its pull-down
  ASSERT_EQ(dance_start(), Status::kOk);
  run_ms(20);
  EXPECT_EQ(fault_reason(), FaultReason::kNone);
  hal_manual::set_pin(kStopPin, false);  // the loop opens
  run_ms(10);
  EXPECT_EQ(fault_level(), static_cast<uint8_t>(FaultLevel::kFatal));
  EXPECT_TRUE(hal_manual::in_safe_state());
}

// The header's contract: a broken wire reads as pressed. A cut loop leaves the pin to its pull
// resistor (the manual backend reads an unconnected pin at its pull's level), so the pull must
// take a normally closed input to its active level.
TEST_F(SafetyInputsTest, ACutEmergencyStopWireStopsTheMachine) {
  ASSERT_EQ(safety.add_emergency_stop(kStopPin), Status::kOk);
  ASSERT_EQ(safety.begin(), Status::kOk);  // nothing drives the pin: the wire is cut
  ASSERT_EQ(dance_start(), Status::kOk);
  run_ms(10);
  EXPECT_EQ(fault_level(), static_cast<uint8_t>(FaultLevel::kFatal));
  EXPECT_TRUE(hal_manual::in_safe_state());
}

TEST_F(SafetyInputsTest, FeedHoldStopsThePlannerAndCycleStartResumesIt) {
  TimeBasedInterpolator planner;
  ASSERT_EQ(planner.begin(), Status::kOk);
  planner.speed_overide = 0.8f;
  ASSERT_EQ(safety.add_feed_hold(kHoldPin, &planner), Status::kOk);
  ASSERT_EQ(safety.add_cycle_start(kStartPin, &planner), Status::kOk);
  ASSERT_EQ(safety.begin(), Status::kOk);
  ASSERT_EQ(dance_start(), Status::kOk);
  hal_manual::set_pin(kHoldPin, true);
  run_ms(10);
  EXPECT_EQ(planner.speed_overide, 0.0f);
  hal_manual::set_pin(kHoldPin, false);
  hal_manual::set_pin(kStartPin, true);
  run_ms(10);
  EXPECT_EQ(planner.speed_overide, 0.8f);
}

}  // namespace
}  // namespace stepdance
