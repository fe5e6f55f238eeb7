// The TBI's planned motion against closed-form kinematics: trapezoids, corners, curves, limits.
#include "stepdance/motion/time_based_interpolator.hpp"

#include <gtest/gtest.h>

#include <math.h>

#include <random>
#include <vector>

#include "hal_manual.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/core/fault.hpp"
#include "support/engine_fixture.hpp"

namespace stepdance {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDt = 40e-6;

class TbiTest : public test_support::EngineFixture {
 protected:
  void SetUp() override {
    EngineFixture::SetUp();
    ASSERT_EQ(tbi.begin(), Status::kOk);
    ASSERT_EQ(dance_start(), Status::kOk);
  }
  /// One frame, with the loop running every frame (as dance_loop does between frames).
  void frame() {
    dance_loop();
    hal_manual::run_frames(1);
    const double x = tbi.output_x.read_absolute();
    const double y = tbi.output_y.read_absolute();
    prev_vx = now_vx;
    prev_vy = now_vy;
    now_vx = (x - last_x) / kDt;
    now_vy = (y - last_y) / kDt;
    if (record) {  // the history costs 24 bytes a frame: long runs check as they go instead
      speeds.push_back(hypot(x - last_x, y - last_y) / kDt);
      vx.push_back(now_vx);
      vy.push_back(now_vy);
    }
    last_x = x;
    last_y = y;
  }
  /// Runs until idle; returns frames taken (bounded).
  int run_until_idle(int limit = 10'000'000) {
    int frames = 0;
    while (!tbi.is_idle() && frames < limit) {
      frame();
      ++frames;
    }
    return frames;
  }
  /// Seconds from the first frame that moved to the last (excludes the start delay).
  double moving_time_s() const {
    size_t first = 0, last = 0;
    bool seen = false;
    for (size_t i = 0; i < speeds.size(); ++i) {
      if (speeds[i] == 0.0) continue;
      if (!seen) first = i;
      seen = true;
      last = i;
    }
    return seen ? (last - first + 1) * kDt : 0.0;
  }
  /// Drops the frames before motion began.
  void trim_start() {
    size_t first = 0;
    while (first < speeds.size() && speeds[first] == 0.0) ++first;
    speeds.erase(speeds.begin(), speeds.begin() + first);
    vx.erase(vx.begin(), vx.begin() + first);
    vy.erase(vy.begin(), vy.begin() + first);
  }
  void add_or_wait(uint8_t mode, double speed, double x, double y) {
    while (tbi.add_move(mode, static_cast<float>(speed), x, y, 0, 0, 0, 0) < 0) frame();
  }

  TimeBasedInterpolator tbi;
  bool record = true;
  std::vector<double> speeds, vx, vy;
  double last_x = 0.0, last_y = 0.0;
  double now_vx = 0.0, now_vy = 0.0, prev_vx = 0.0, prev_vy = 0.0;  // this frame's and the last
};

TEST_F(TbiTest, SingleMoveTakesTheTrapezoidTime) {
  tbi.set_acceleration(1000.0);
  tbi.add_move(ABSOLUTE, 50.0f, 100.0, 0, 0, 0, 0, 0);
  run_until_idle();
  // From rest to rest: ramps of v/a each cover v²/a in total, the rest is cruised: t = L/v + v/a.
  const double expected_s = 100.0 / 50.0 + 50.0 / 1000.0;
  EXPECT_NEAR(moving_time_s(), expected_s, 3 * kDt);
  EXPECT_DOUBLE_EQ(tbi.output_x.read_absolute(), 100.0);
}

TEST_F(TbiTest, ShortMoveNeverReachesCruiseAndPeaksAtTheTriangleSpeed) {
  tbi.set_acceleration(1000.0);
  tbi.add_move(ABSOLUTE, 500.0f, 1.0, 0, 0, 0, 0, 0);
  run_until_idle();
  // Triangle: peak √(aL) = √1000, time 2·√(L/a).
  EXPECT_NEAR(moving_time_s(), 2.0 * sqrt(1.0 / 1000.0), 3 * kDt);
  double peak = 0;
  for (double v : speeds) peak = fmax(peak, v);
  EXPECT_NEAR(peak, sqrt(1000.0), 1000.0 * kDt * 1.5);
}

TEST_F(TbiTest, RightAngleCornerAtTheJunctionDeviationSpeed) {
  const double a = 1000.0, delta = 0.05;
  tbi.set_acceleration(a);
  tbi.set_junction_deviation(delta);
  tbi.add_move(ABSOLUTE, 50.0f, 20.0, 0, 0, 0, 0, 0);
  tbi.add_move(ABSOLUTE, 50.0f, 20.0, 20.0, 0, 0, 0, 0);
  run_until_idle();
  // θ = 90°: v² = a·δ·sin45° / (1 − sin45°). (The centripetal bound a·(L/2)·tan45° = 10⁴ is looser.)
  const double s = sin(kPi / 4.0);
  const double expected = sqrt(a * delta * s / (1.0 - s));
  // The corner frame: where y starts moving. Its speed before and after brackets the corner.
  size_t corner = 0;
  while (corner < vy.size() && vy[corner] == 0.0) ++corner;
  ASSERT_LT(corner, vy.size());
  EXPECT_NEAR(fabs(vx[corner - 1]), expected, a * kDt * 1.5);
  EXPECT_NEAR(vy[corner + 1], expected, a * kDt * 1.5);
}

TEST_F(TbiTest, ThousandCollinearSegmentsFlowAtFullSpeed) {
  const double a = 1000.0, v = 40.0;
  tbi.set_acceleration(a);
  for (int i = 1; i <= 1000; ++i) add_or_wait(ABSOLUTE, v, i * 0.1, 0.0);
  run_until_idle();
  trim_start();
  EXPECT_DOUBLE_EQ(tbi.output_x.read_absolute(), 100.0);
  // Once accelerated (v/a = 40 ms), every frame until the final ramp moves at full speed.
  const size_t ramp = static_cast<size_t>(v / a / kDt) + 2;
  ASSERT_GT(speeds.size(), 2 * ramp);
  for (size_t i = ramp; i + ramp < speeds.size(); ++i)
    ASSERT_NEAR(speeds[i], v, 1e-6) << "frame " << i << " of " << speeds.size();
  EXPECT_NEAR(moving_time_s(), 100.0 / v + v / a, 3 * kDt);
  EXPECT_EQ(tbi.underruns(), 0u);
}

TEST_F(TbiTest, ThreeThousandShortSegmentsPerSecondNeverRunDry) {
  // 0.02 mm segments along a gentle arc (R = 100 mm) at 60 mm/s: 3,000 segments a second, with
  // the loop (planning) running only every fifth frame (200 µs, the simulator's loop period).
  tbi.set_acceleration(1500.0);
  const double radius = 100.0, v = 60.0, segment = 0.02;
  const int count = 4000;
  record = false;
  int next = 1, frames = 0;
  double peak = 0.0, slowest_cruise = 1e9;
  while ((next <= count || !tbi.is_idle()) && frames < 1'000'000) {
    if (frames % 5 == 0) {
      while (next <= count && !tbi.queue_is_full()) {
        const double angle = next * segment / radius;
        tbi.add_move(ABSOLUTE, static_cast<float>(v), radius * sin(angle), radius * (1 - cos(angle)), 0, 0, 0, 0);
        ++next;
      }
      dance_loop();
    }
    hal_manual::run_frames(1);
    ++frames;
    const double x = tbi.output_x.read_absolute(), y = tbi.output_y.read_absolute();
    const double speed = hypot(x - last_x, y - last_y) / kDt;
    last_x = x;
    last_y = y;
    peak = fmax(peak, speed);
    // Between the ramps (0.3 s after the start delay, until 0.05 s before the end) it cruises.
    const double t = frames * kDt;
    if (t > 0.1 && t < count * segment / v - 0.1) slowest_cruise = fmin(slowest_cruise, speed);
  }
  EXPECT_EQ(tbi.underruns(), 0u);
  EXPECT_NEAR(peak, v, 1e-6);
  EXPECT_NEAR(slowest_cruise, v, 1e-6);
  const double end_angle = count * segment / radius;
  EXPECT_NEAR(tbi.output_x.read_absolute(), radius * sin(end_angle), 1e-9);
}

TEST_F(TbiTest, ThousandSegmentCircleRunsAtItsCentripetalLimit) {
  const double a = 1000.0, radius = 50.0;
  tbi.set_acceleration(a);
  tbi.set_junction_deviation(1.0);  // generous: the curve, not the corner model, must limit
  tbi.add_move(ABSOLUTE, 1000.0f, radius, 0.0, 0, 0, 0, 0);
  run_until_idle();
  speeds.clear();
  last_x = radius;
  last_y = 0.0;
  const int n = 1000;
  for (int i = 1; i <= n; ++i)
    add_or_wait(ABSOLUTE, 1000.0, radius * cos(2 * kPi * i / n), radius * sin(2 * kPi * i / n));
  run_until_idle();
  // Centripetal: v² = a·R at each vertex, with R the circle through the chords' midpoints
  // (R·cos(π/N)); between vertices a chord of length L may speed up to √(v² + a·L) and back.
  const double chord = 2.0 * radius * sin(kPi / n);
  const double at_vertex = sqrt(a * radius * cos(kPi / n));
  const double between = sqrt(at_vertex * at_vertex + a * chord);
  const size_t quarter = speeds.size() / 4;
  for (size_t i = quarter; i < 3 * quarter; ++i) {
    ASSERT_GE(speeds[i], at_vertex * (1 - 1e-3)) << "frame " << i;
    ASSERT_LE(speeds[i], between * (1 + 1e-3)) << "frame " << i;
  }
  EXPECT_NEAR(tbi.output_x.read_absolute(), radius, 1e-9);
  EXPECT_NEAR(tbi.output_y.read_absolute(), 0.0, 1e-9);
}

TEST_F(TbiTest, CoreXyMotorLimitsHoldFrameByFrame) {
  const double motor_speed = 60.0, motor_acceleration = 800.0;
  tbi.limits().use_core_xy(motor_speed, motor_acceleration);
  tbi.set_acceleration(1e9);  // only the motors limit
  tbi.set_junction_deviation(0.0001);
  // Collinear pieces in several directions, separated by full stops (reversals).
  const double targets[][2] = {{30, 0}, {30, 30}, {0, 0}, {10, 25}, {40, 5}};
  for (const auto& target : targets) tbi.add_move(ABSOLUTE, 500.0f, target[0], target[1], 0, 0, 0, 0);
  record = false;
  int jumps = 0;
  for (int frames = 0; !tbi.is_idle() && frames < 10'000'000; ++frames) {
    frame();
    const double motor_a = now_vx + now_vy, motor_b = now_vx - now_vy;
    ASSERT_LE(fabs(motor_a), motor_speed * (1 + 1e-9)) << "frame " << frames;
    ASSERT_LE(fabs(motor_b), motor_speed * (1 + 1e-9)) << "frame " << frames;
    // Acceleration within moves: successive frames differ by at most a·dt, except where the
    // junction model allows a jump at a corner (bounded below).
    const double da = fabs(motor_a - (prev_vx + prev_vy)) / kDt;
    const double db = fabs(motor_b - (prev_vx - prev_vy)) / kDt;
    if (fmax(da, db) <= motor_acceleration * 1.01) continue;
    ++jumps;
    // A corner changes direction at the junction speed v_j: each motor's speed jumps by at most
    // 2·√2·v_j (v_j² = a·δ·sin(θ/2)/(1 − sin(θ/2)) ≤ a·δ·1e3 for any corner over 0.1°).
    const double v_j_bound = sqrt(motor_acceleration * 0.0001 * 1e3);
    ASSERT_LE(fmax(da, db) * kDt, 2.0 * sqrt(2.0) * v_j_bound + motor_acceleration * kDt) << "frame " << frames;
  }
  EXPECT_LE(jumps, 2 * 4);  // at most two frames around each of the four corners
  EXPECT_DOUBLE_EQ(tbi.output_x.read_absolute(), 40.0);
  EXPECT_DOUBLE_EQ(tbi.output_y.read_absolute(), 5.0);
}

TEST_F(TbiTest, ExactEndpointsAfterManyRandomMovesAndOverrideChanges) {
  std::mt19937 random(1234);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> speed(5.0, 200.0);
  std::uniform_real_distribution<double> override_factor(0.0, 2.0);
  record = false;
  double x = 0, y = 0;
  for (int i = 0; i < 10000; ++i) {
    // Mostly short moves (so the run stays short), a long one every hundred, inside ±50.
    const double reach = (i % 100 == 0) ? 50.0 : 0.5;
    x = fmax(-50.0, fmin(50.0, x + reach * unit(random)));
    y = fmax(-50.0, fmin(50.0, y + reach * unit(random)));
    add_or_wait(ABSOLUTE, speed(random), x, y);
    if (i % 7 == 0) tbi.speed_overide = static_cast<float>(override_factor(random));
    if (i % 50 == 0) tbi.speed_overide = 1.0f;  // never stuck paused for long
    frame();
  }
  tbi.speed_overide = 1.0f;
  run_until_idle();
  EXPECT_EQ(tbi.output_x.read_absolute(), x);
  EXPECT_EQ(tbi.output_y.read_absolute(), y);
}

TEST_F(TbiTest, OverrideZeroPausesSmoothlyAndResumes) {
  const double a = 500.0;
  tbi.set_acceleration(a);
  tbi.add_move(ABSOLUTE, 50.0f, 100.0, 0, 0, 0, 0, 0);
  for (int i = 0; i < 10000; ++i) frame();
  tbi.speed_overide = 0.0f;
  for (int i = 0; i < 10000; ++i) frame();
  for (size_t i = 1; i < speeds.size(); ++i) ASSERT_LE(fabs(speeds[i] - speeds[i - 1]), a * kDt * 1.0001);
  EXPECT_EQ(speeds.back(), 0.0);
  const double paused_at = tbi.output_x.read_absolute();
  EXPECT_GT(paused_at, 0.0);
  EXPECT_LT(paused_at, 100.0);
  tbi.speed_overide = 1.0f;
  run_until_idle();
  EXPECT_DOUBLE_EQ(tbi.output_x.read_absolute(), 100.0);
}

TEST_F(TbiTest, ResetDeceleratesWithinTheLimitThenDropsTheQueue) {
  const double a = 800.0;
  tbi.set_acceleration(a);
  for (int i = 1; i <= 10; ++i) tbi.add_move(ABSOLUTE, 40.0f, i * 10.0, 0, 0, 0, 0, 0);
  for (int i = 0; i < 20000; ++i) frame();
  ASSERT_NEAR(speeds.back(), 40.0, 1e-6);
  tbi.reset_block_queue();
  const int frames = run_until_idle();
  // Stopping from v at a takes v/a; add a frame for the command to reach the frame and one for
  // the loop to see the stop complete.
  EXPECT_NEAR(frames * kDt, 40.0 / a + 2 * kDt, 2 * kDt);
  for (size_t i = 1; i < speeds.size(); ++i) ASSERT_LE(fabs(speeds[i] - speeds[i - 1]), a * kDt * 1.0001);
  EXPECT_TRUE(tbi.is_idle());
  const double stopped = tbi.output_x.read_absolute();
  EXPECT_LT(stopped, 100.0);
  tbi.add_move(INCREMENTAL, 40.0f, 1.0, 0, 0, 0, 0, 0);  // new moves start from where it stopped
  run_until_idle();
  EXPECT_DOUBLE_EQ(tbi.output_x.read_absolute(), stopped + 1.0);
}

TEST_F(TbiTest, ZeroLengthAndZeroTimeMovesNeverStall) {
  EXPECT_GE(tbi.add_move(ABSOLUTE, 10.0f, 0, 0, 0, 0, 0, 0), 0);
  EXPECT_GE(tbi.add_timed_move(INCREMENTAL, 0.0f, 0, 0, 0, 0, 0, 0), 0);
  EXPECT_TRUE(tbi.is_idle());
  EXPECT_EQ(tbi.add_move(ABSOLUTE, 0.0f, 5, 0, 0, 0, 0, 0), -1);           // no speed, no time: refused
  EXPECT_GE(tbi.add_timed_move(INCREMENTAL, 0.01f, 0, 0, 0, 0, 0, 0), 0);  // a 10 ms dwell
  const int frames = run_until_idle();
  const double start_delay_s = TimeBasedInterpolator::kStartDelayUs * 1e-6;
  EXPECT_NEAR(frames * kDt, start_delay_s + 0.01, 2 * kDt);
}

TEST_F(TbiTest, FullQueueRefusesAndNeverOverwrites) {
  record = false;
  int accepted = 0;
  while (tbi.add_move(INCREMENTAL, 10.0f, 1.0, 0, 0, 0, 0, 0) >= 0) ++accepted;
  EXPECT_TRUE(tbi.queue_is_full());
  EXPECT_EQ(tbi.slots_remaining, 0);
  EXPECT_GE(accepted, 32);
  run_until_idle();
  EXPECT_DOUBLE_EQ(tbi.output_x.read_absolute(), accepted * 1.0);
}

TEST_F(TbiTest, TimedMoveHonoursItsDuration) {
  tbi.set_acceleration(1e6);  // ramps of 10 µs: the duration is the move time
  tbi.add_timed_move(ABSOLUTE, 0.5f, 10.0, 0, 0, 0, 0, 0);
  run_until_idle();
  EXPECT_NEAR(moving_time_s(), 0.5, 3 * kDt);
}

TEST_F(TbiTest, ExtruderOnlyMoveUsesItsOwnLength) {
  tbi.set_acceleration(1e6);
  tbi.add_move(ABSOLUTE, 5.0f, 0, 0, 0, 10.0, 0, 0);  // 10 mm of E at 5 mm/s: 2 s
  const int frames = run_until_idle();
  EXPECT_NEAR(frames * kDt, TimeBasedInterpolator::kStartDelayUs * 1e-6 + 2.0, 3 * kDt);
  EXPECT_DOUBLE_EQ(tbi.output_e.read_absolute(), 10.0);
}

TEST_F(TbiTest, AlarmStopsPlannedMotionAndRefusesMoves) {
  tbi.set_acceleration(1000.0);
  tbi.add_move(ABSOLUTE, 50.0f, 100.0, 0, 0, 0, 0, 0);
  for (int i = 0; i < 5000; ++i) frame();
  report_fault(FaultLevel::kAlarm, FaultReason::kLimitHit, "test", "limit");
  const int frames = run_until_idle(100000);
  EXPECT_NEAR(frames * kDt, 50.0 / 1000.0, 3 * kDt);
  EXPECT_EQ(tbi.add_move(ABSOLUTE, 50.0f, 0, 0, 0, 0, 0, 0), -1);
  clear_alarm();
  EXPECT_GE(tbi.add_move(ABSOLUTE, 50.0f, 0, 0, 0, 0, 0, 0), 0);
  run_until_idle();
  EXPECT_DOUBLE_EQ(tbi.output_x.read_absolute(), 0.0);
}

}  // namespace
}  // namespace stepdance
