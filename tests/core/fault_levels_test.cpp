// The three fault levels end to end: who is told (a subscriber, in the loop), what stops, what
// keeps running, and how each is cleared.
#include <gtest/gtest.h>

#include <vector>

#include "hal_manual.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/core/fault.hpp"
#include "stepdance/motion/position_generator.hpp"
#include "stepdance/motion/time_based_interpolator.hpp"
#include "support/engine_fixture.hpp"

namespace stepdance {
namespace {

std::vector<FaultReport> told;
bool inside_frame = false;
bool told_inside_frame = false;

void subscriber(const FaultReport& report) {
  told.push_back(report);
  if (inside_frame) told_inside_frame = true;
}

class FaultLevelsTest : public test_support::EngineFixture {
 protected:
  void SetUp() override {
    EngineFixture::SetUp();
    told.clear();
    told_inside_frame = false;
    ASSERT_TRUE(on_fault(&subscriber));
    ASSERT_EQ(planned.begin(), Status::kOk);
    live.begin();
    ASSERT_EQ(dance_start(), Status::kOk);
  }
  void run(int frames) {
    for (int i = 0; i < frames; ++i) {
      dance_loop();
      hal_manual::run_frames(1);
    }
  }
  TimeBasedInterpolator planned;  // pre-planned motion
  PositionGenerator live;         // a live input (as a knob-driven generator)
};

TEST_F(FaultLevelsTest, WarningIsCountedAndToldWhileMotionGoesOn) {
  planned.add_move(ABSOLUTE, 50.0f, 100.0, 0, 0, 0, 0, 0);
  run(2000);
  const double before = planned.output_x.read_absolute();
  report_fault(FaultLevel::kWarning, FaultReason::kUnreachable, "kinematics", "pose out of reach");
  EXPECT_TRUE(told.empty());  // not from inside report_fault: subscribers run in the loop
  run(1000);
  ASSERT_EQ(told.size(), 1u);
  EXPECT_EQ(told[0].level, FaultLevel::kWarning);
  EXPECT_EQ(told[0].reason, FaultReason::kUnreachable);
  EXPECT_STREQ(told[0].source, "kinematics");
  EXPECT_EQ(warning_count(), 1u);
  EXPECT_EQ(fault_level(), static_cast<uint8_t>(FaultLevel::kWarning));
  EXPECT_GT(planned.output_x.read_absolute(), before);  // still moving
  EXPECT_TRUE(hal_manual::frame_timer_running());
}

TEST_F(FaultLevelsTest, AlarmStopsPlannedMotionKeepsLiveInputsAndClearsExplicitly) {
  const double a = TimeBasedInterpolator::kDefaultAccelerationPerS2;
  planned.add_move(ABSOLUTE, 50.0f, 100.0, 0, 0, 0, 0, 0);
  run(20000);  // cruising at 50 mm/s
  report_fault(FaultLevel::kAlarm, FaultReason::kLimitHit, "limit", "X limit");
  run(2);
  ASSERT_EQ(told.size(), 1u);
  EXPECT_EQ(told[0].level, FaultLevel::kAlarm);
  EXPECT_TRUE(alarm_active());
  EXPECT_EQ(fault_level(), static_cast<uint8_t>(FaultLevel::kAlarm));
  // Planned motion decelerates within the limit: stopped after v/a, having gone v²/2a further.
  const double at_alarm = planned.output_x.read_absolute();
  run(static_cast<int>(50.0 / a / 40e-6) + 10);
  EXPECT_TRUE(planned.is_idle());
  EXPECT_NEAR(planned.output_x.read_absolute() - at_alarm, 50.0 * 50.0 / (2 * a), 0.01);
  EXPECT_EQ(planned.add_move(ABSOLUTE, 50.0f, 0, 0, 0, 0, 0, 0), -1);  // refused while alarmed
  // A live input keeps working during the alarm.
  live.go(5.0, ABSOLUTE, 100.0);
  run(5000);
  EXPECT_DOUBLE_EQ(live.output.read_absolute(), 5.0);
  // Cleared explicitly: planned motion is accepted again.
  clear_alarm();
  EXPECT_FALSE(alarm_active());
  EXPECT_GE(planned.add_move(ABSOLUTE, 50.0f, 0, 0, 0, 0, 0, 0), 0);
  EXPECT_TRUE(hal_manual::frame_timer_running());
}

TEST_F(FaultLevelsTest, FatalStopsEverythingAtOnceUntilRestart) {
  planned.add_move(ABSOLUTE, 50.0f, 100.0, 0, 0, 0, 0, 0);
  run(20000);
  report_fault(FaultLevel::kFatal, FaultReason::kInvariant, "engine", "broken invariant");
  EXPECT_TRUE(hal_manual::in_safe_state());         // outputs safe, drivers disabled
  EXPECT_FALSE(hal_manual::frame_timer_running());  // frames stopped at once
  const double frozen = planned.output_x.read_absolute();
  run(1000);
  EXPECT_EQ(planned.output_x.read_absolute(), frozen);
  ASSERT_EQ(told.size(), 1u);
  EXPECT_EQ(told[0].level, FaultLevel::kFatal);
  EXPECT_EQ(fault_level(), static_cast<uint8_t>(FaultLevel::kFatal));
  clear_alarm();  // does not clear a fatal fault
  EXPECT_EQ(fault_level(), static_cast<uint8_t>(FaultLevel::kFatal));
  EXPECT_EQ(fault_reason(), FaultReason::kInvariant);
}

void report_from_frame() {
  inside_frame = true;
  report_fault(FaultLevel::kWarning, FaultReason::kOverrun, "frame", "from the frame");
  inside_frame = false;
}

TEST_F(FaultLevelsTest, ReportsFromTheFrameReachSubscribersInTheLoop) {
  ASSERT_EQ(add_function_to_frame(&report_from_frame), Status::kOk);
  hal_manual::run_frames(3);  // three reports, no loop pass yet
  EXPECT_TRUE(told.empty());
  dance_loop();
  ASSERT_EQ(told.size(), 3u);
  EXPECT_FALSE(told_inside_frame);
  EXPECT_EQ(told[0].sequence + 1, told[1].sequence);
  FaultReport newest;
  ASSERT_TRUE(recent_fault_report(0, newest));
  EXPECT_EQ(newest.sequence, told[2].sequence);
}

TEST_F(FaultLevelsTest, ReportsBeyondTheHistoryAreCountedAsLost) {
  for (uint32_t i = 0; i < kFaultReportHistory + 4; ++i) {
    report_fault(FaultLevel::kWarning, FaultReason::kRefused, "test", "burst");
  }
  dance_loop();
  EXPECT_EQ(told.size(), kFaultReportHistory);
  EXPECT_EQ(fault_reports_lost(), 4u);
  EXPECT_EQ(told.back().sequence, kFaultReportHistory + 4);
}

// Every warning is tallied by its source and reason, so a run can list each with its count:
// the first report's detail stays with its kind; count_warning() adds to a kind without a report.
TEST_F(FaultLevelsTest, WarningsAreTalliedBySourceAndReason) {
  report_fault(FaultLevel::kWarning, FaultReason::kOverrun, "Eibotboard", "first stretch");
  for (int i = 0; i < 4; ++i) count_warning(FaultReason::kOverrun, "Eibotboard");
  report_fault(FaultLevel::kWarning, FaultReason::kUnreachable, "kinematics", "pose out of reach");
  report_fault(FaultLevel::kWarning, FaultReason::kUnreachable, "kinematics", "another pose");
  report_fault(FaultLevel::kAlarm, FaultReason::kLimitHit, "homing", "not a warning");
  EXPECT_EQ(warning_count(), 7u);
  WarningTally tally;
  ASSERT_TRUE(warning_tally(0, tally));
  EXPECT_STREQ(tally.source, "Eibotboard");
  EXPECT_EQ(tally.reason, FaultReason::kOverrun);
  EXPECT_STREQ(tally.detail, "first stretch");
  EXPECT_EQ(tally.count, 5u);
  ASSERT_TRUE(warning_tally(1, tally));
  EXPECT_STREQ(tally.source, "kinematics");
  EXPECT_STREQ(tally.detail, "pose out of reach");
  EXPECT_EQ(tally.count, 2u);
  EXPECT_FALSE(warning_tally(2, tally));
  dance_loop();
  EXPECT_EQ(told.size(), 4u);  // count_warning() made no report
  clear_fault();
  EXPECT_FALSE(warning_tally(0, tally));
}

TEST_F(FaultLevelsTest, SubscribersAreBounded) {
  auto other = [](const FaultReport&) {};
  for (uint32_t i = 1; i < kMaxFaultSubscribers; ++i) EXPECT_TRUE(on_fault(other));
  EXPECT_FALSE(on_fault(other));
  EXPECT_FALSE(on_fault(nullptr));
}

}  // namespace
}  // namespace stepdance
