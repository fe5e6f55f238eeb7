// Unit tests of Homing and HomingAxis against a simulated switch on a stepping axis: random
// starts end within one step of the switch, the pull-off and slow approach show in the step log,
// a switch that never closes times out into an alarm, and bounce shorter than the debounce
// time does not stop the seek.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include "hal_manual.hpp"
#include "recording/recording_test_support.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/core/fault.hpp"
#include "stepdance/homing/homing.hpp"
#include "stepdance/motion/channel.hpp"
#include "support/engine_fixture.hpp"

namespace stepdance {
namespace {

constexpr uint8_t kSwitchPin = 30;
constexpr double kStepsPerMm = 80.0;
constexpr double kStepMm = 1.0 / kStepsPerMm;
constexpr double kSwitchMm = 5.0;  // the switch closes at or below 5 mm of real carriage position

class HomingTest : public test_support::EngineFixture {
 protected:
  void SetUp() override {
    EngineFixture::SetUp();
    channel.set_ratio(1.0, kStepsPerMm);
    ASSERT_EQ(channel.begin(nullptr, SIGNAL_X), Status::kOk);
  }

  void start(double start_mm) {
    start_mm_ = start_mm;
    ASSERT_EQ(homing.begin(), Status::kOk);
    ASSERT_EQ(dance_start(), Status::kOk);
    homing.start_homing_routine();
  }

  /// The carriage's real position: where it started plus the steps the channel emitted.
  double carriage_mm() const {
    return start_mm_ + (static_cast<double>(channel.pulses_forward()) - channel.pulses_reverse()) * kStepMm;
  }

  /// Runs frames until homing ends (or `limit` frames), with the switch following the carriage
  /// (glitch(frame) may force it closed), logging the carriage position and the axis state.
  void run_homing(uint32_t limit, const std::function<bool(uint32_t)>& glitch = nullptr) {
    for (uint32_t frame = 0; frame < limit; ++frame) {
      const bool closed = carriage_mm() <= kSwitchMm + 1e-9 || (glitch && glitch(frame));
      hal_manual::set_pin(kSwitchPin, closed);
      hal_manual::run_frames(1);
      positions.push_back(carriage_mm());
      states.push_back(homing.axis(0).state());
      if (frame % 5 == 0) dance_loop();
      if (!homing.is_homing()) return;
    }
  }

  /// The states the axis went through, each once, in order.
  std::vector<uint8_t> state_sequence() const {
    std::vector<uint8_t> sequence;
    for (uint8_t state : states) {
      if (sequence.empty() || sequence.back() != state) sequence.push_back(state);
    }
    return sequence;
  }

  Channel channel;
  Homing homing;
  std::vector<double> positions;
  std::vector<uint8_t> states;
  double start_mm_ = 0;
};

TEST_F(HomingTest, RandomStartsEndWithinOneStepOfTheSwitch) {
  std::mt19937 random(42);
  std::uniform_real_distribution<double> anywhere(0.0, 60.0);
  for (int run = 0; run < 12; ++run) {
    test_support::reset_global_state();
    Channel axis_channel;
    axis_channel.set_ratio(1.0, kStepsPerMm);
    ASSERT_EQ(axis_channel.begin(nullptr, SIGNAL_X), Status::kOk);
    Homing routine;
    ASSERT_EQ(routine.add_axis(kSwitchPin, 0.0, HOMING_DIR_BWD, 20.0f, &axis_channel.input_target_position),
              Status::kOk);
    ASSERT_EQ(routine.begin(), Status::kOk);
    ASSERT_EQ(dance_start(), Status::kOk);
    const double start = anywhere(random);
    auto carriage = [&] {
      return start + (static_cast<double>(axis_channel.pulses_forward()) - axis_channel.pulses_reverse()) * kStepMm;
    };
    routine.start_homing_routine();
    for (uint32_t frame = 0; frame < 25000 * 20 && routine.is_homing(); ++frame) {
      hal_manual::set_pin(kSwitchPin, carriage() <= kSwitchMm + 1e-9);
      hal_manual::run_frames(1);
      if (frame % 5 == 0) dance_loop();
    }
    ASSERT_TRUE(routine.is_homed()) << "start " << start;
    // The machine now calls the switch point 0: real position − switch = reported position − 0.
    const double reported_mm = axis_channel.current_position / kStepsPerMm;
    EXPECT_NEAR(carriage() - kSwitchMm, reported_mm, kStepMm) << "start " << start;
    // It rests a pull-off (1 mm) off the switch.
    EXPECT_NEAR(reported_mm, 1.0, kStepMm) << "start " << start;
  }
}

TEST_F(HomingTest, StepLogShowsFastSeekPullOffSlowApproachAndPullOff) {
  ASSERT_EQ(homing.add_axis(kSwitchPin, 0.0, HOMING_DIR_BWD, 20.0f, &channel.input_target_position), Status::kOk);
  homing.axis(0).set_slow_velocity(1.0);
  homing.axis(0).set_pull_off_distance(2.0);
  start(30.0);
  run_homing(25000 * 10);
  ASSERT_TRUE(homing.is_homed());
  // BEGIN lasts no whole frame: the first frame already decides to seek.
  const std::vector<uint8_t> expected = {HOMING_AXIS_STATE_SEEKING, HOMING_AXIS_STATE_PULLING_OFF,
                                         HOMING_AXIS_STATE_APPROACHING, HOMING_AXIS_STATE_FINAL_PULL_OFF,
                                         HOMING_AXIS_STATE_FINISHED};
  EXPECT_EQ(state_sequence(), expected);
  // Speeds from the step log over 50 ms of each phase (from 4 ms in), mm/s.
  auto speed_in = [&](uint8_t state) {
    size_t first = 0;
    while (states[first] != state) ++first;
    const size_t frames = 1250;  // 50 ms: the 2 mm pull-off at 20 mm/s lasts 100 ms
    return (positions[first + 100 + frames] - positions[first + 100]) / (frames * 40e-6);
  };
  EXPECT_NEAR(speed_in(HOMING_AXIS_STATE_SEEKING), -20.0, 0.5);
  EXPECT_NEAR(speed_in(HOMING_AXIS_STATE_PULLING_OFF), 20.0, 0.5);
  EXPECT_NEAR(speed_in(HOMING_AXIS_STATE_APPROACHING), -1.0, 0.05);
  // The pull-off moved 2 mm away from where the fast seek stopped.
  size_t pull = 0;
  while (states[pull] != HOMING_AXIS_STATE_PULLING_OFF) ++pull;
  size_t approach = pull;
  while (states[approach] != HOMING_AXIS_STATE_APPROACHING) ++approach;
  EXPECT_NEAR(positions[approach] - positions[pull], 2.0, 2 * kStepMm);
  EXPECT_NEAR(positions.back(), kSwitchMm + 2.0, kStepMm);
}

TEST_F(HomingTest, ASwitchThatNeverClosesTimesOutIntoAnAlarm) {
  ASSERT_EQ(homing.add_axis(kSwitchPin, 0.0, HOMING_DIR_BWD, 20.0f, &channel.input_target_position), Status::kOk);
  homing.axis(0).set_timeout_ms(500);
  static int failures = 0;
  failures = 0;
  homing.set_callback_on_failed([] { ++failures; });
  start(1000.0);  // the switch is 995 mm away: it never closes within the timeout
  run_homing(25000);
  EXPECT_FALSE(homing.is_homing());
  EXPECT_TRUE(homing.has_failed());
  EXPECT_FALSE(homing.is_homed());
  EXPECT_EQ(failures, 1);
  EXPECT_TRUE(alarm_active());
  FaultReport report;
  ASSERT_TRUE(recent_fault_report(0, report));
  EXPECT_EQ(report.reason, FaultReason::kTimeout);
  // 500 ms at 20 mm/s: 10 mm of seeking, then it stopped.
  EXPECT_NEAR(positions.back(), 1000.0 - 10.0, 0.1);
  const double stopped_at = carriage_mm();
  hal_manual::run_frames(1000);
  EXPECT_EQ(carriage_mm(), stopped_at);
}

TEST_F(HomingTest, MaximumTravelStopsASeekThatFindsNothing) {
  ASSERT_EQ(homing.add_axis(kSwitchPin, 0.0, HOMING_DIR_BWD, 20.0f, &channel.input_target_position), Status::kOk);
  homing.axis(0).set_max_travel(3.0);
  start(1000.0);
  run_homing(25000);
  EXPECT_TRUE(homing.has_failed());
  EXPECT_NEAR(carriage_mm(), 1000.0 - 3.0, 2 * kStepMm);
}

// A 1 ms glitch (25 frames) while seeking, 10 mm before the switch.
bool glitch_at_15mm(uint32_t frame) {
  // At 20 mm/s from 30 mm the carriage passes 15 mm after 0.75 s = 18 750 frames.
  return frame >= 18750 && frame < 18775;
}

TEST_F(HomingTest, BounceShorterThanTheDebounceTimeDoesNotStopTheSeek) {
  ASSERT_EQ(homing.add_axis(kSwitchPin, 0.0, HOMING_DIR_BWD, 20.0f, &channel.input_target_position), Status::kOk);
  homing.axis(0).set_debounce_ms(2.0);
  start(30.0);
  run_homing(25000 * 10, glitch_at_15mm);
  ASSERT_TRUE(homing.is_homed());
  EXPECT_EQ(states[18780], HOMING_AXIS_STATE_SEEKING);
  EXPECT_NEAR(carriage_mm() - kSwitchMm, channel.current_position / kStepsPerMm, kStepMm);
}

TEST_F(HomingTest, TheSameGlitchStopsASeekWithAShorterDebounce) {
  ASSERT_EQ(homing.add_axis(kSwitchPin, 0.0, HOMING_DIR_BWD, 20.0f, &channel.input_target_position), Status::kOk);
  homing.axis(0).set_debounce_ms(0.5);
  start(30.0);
  run_homing(25000 * 10, glitch_at_15mm);
  EXPECT_NE(states[18780], HOMING_AXIS_STATE_SEEKING);
}

TEST_F(HomingTest, OtherSourcesOnTheTargetAreHeldOffWhileHoming) {
  test_support::ScriptedSource knob;
  knob.begin();
  knob.output.map(&channel.input_target_position);
  ASSERT_EQ(homing.add_axis(kSwitchPin, 0.0, HOMING_DIR_BWD, 20.0f, &channel.input_target_position), Status::kOk);
  knob.play(std::vector<double>(25000 * 20, 0.001));  // 25 mm/s away from the switch, all along
  start(30.0);
  run_homing(25000 * 10);
  ASSERT_TRUE(homing.is_homed());
  EXPECT_NEAR(carriage_mm() - kSwitchMm, channel.current_position / kStepsPerMm, kStepMm);
  EXPECT_TRUE(knob.output.is_enabled());
  const double homed_at = carriage_mm();
  hal_manual::run_frames(2500);  // the knob moves the axis again: 0.1 s × 25 mm/s
  EXPECT_NEAR(carriage_mm() - homed_at, 2.5, 2 * kStepMm);
}

}  // namespace
}  // namespace stepdance
