// Generators, filters and polar kinematics against closed-form geometry.
#include <gtest/gtest.h>

#include <math.h>

#include "hal_manual.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/core/fault.hpp"
#include "stepdance/motion/angle_source.hpp"
#include "stepdance/motion/attractor_2d.hpp"
#include "stepdance/motion/circle_generator.hpp"
#include "stepdance/motion/kinematics_five_bar.hpp"
#include "stepdance/motion/kinematics_polar_to_cartesian.hpp"
#include "stepdance/motion/path_length_generator.hpp"
#include "stepdance/motion/position_generator.hpp"
#include "stepdance/motion/scaling_filter.hpp"
#include "stepdance/motion/threshold_generator.hpp"
#include "stepdance/motion/vector_2d_to_angle.hpp"
#include "stepdance/motion/velocity_generator.hpp"
#include "stepdance/motion/wave_generator_1d.hpp"
#include "stepdance/motion/wave_generator_2d.hpp"
#include "support/engine_fixture.hpp"

namespace stepdance {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDt = 40e-6;
constexpr double kStepMm = 1.0 / 80.0;  // one motor step on an 80 steps/mm belt

class GeneratorsTest : public test_support::EngineFixture {};

TEST_F(GeneratorsTest, CircleClosesWithinOneStepAfterTenThousandTurns) {
  CircleGenerator circle;
  ASSERT_EQ(circle.begin(), Status::kOk);
  circle.setNoInput();
  circle.radius = 10.0f;
  circle.rotational_speed_rev_per_sec = static_cast<float>(2 * kPi * 100);  // rad/s: 100 turns/s
  ASSERT_EQ(dance_start(), Status::kOk);
  // Check the shape on the way (closed form: x = r sin θ, y = r(1 − cos θ), θ from the float rate).
  const double rate = static_cast<double>(circle.rotational_speed_rev_per_sec);
  hal_manual::run_frames(37);
  EXPECT_NEAR(circle.output_x.read_absolute(), 10 * sin(rate * 37 * kDt), 1e-9);
  EXPECT_NEAR(circle.output_y.read_absolute(), 10 * (1 - cos(rate * 37 * kDt)), 1e-9);
  // 10,000 turns: the frame count whose angle is closest to a whole number of turns.
  const double frames_per_turn = 2 * kPi / (rate * kDt);
  const uint32_t frames = static_cast<uint32_t>(llround(10000 * frames_per_turn)) - 37;
  hal_manual::run_frames(frames);
  const double theta = rate * (frames + 37) * kDt;
  EXPECT_NEAR(circle.output_x.read_absolute(), 10 * sin(theta), 1e-6);
  EXPECT_NEAR(circle.output_y.read_absolute(), 10 * (1 - cos(theta)), 1e-6);
  EXPECT_LT(hypot(circle.output_x.read_absolute(), circle.output_y.read_absolute()),
            kStepMm + 10 * fabs(remainder(theta, 2 * kPi)));  // back at the start, to a step
}

TEST_F(GeneratorsTest, CircleWhoseRadiusChangesMovesContinuously) {
  CircleGenerator circle;
  ASSERT_EQ(circle.begin(), Status::kOk);
  circle.setNoInput();
  circle.radius = 5.0f;
  circle.rotational_speed_rev_per_sec = 10.0f;  // rad/s
  ASSERT_EQ(dance_start(), Status::kOk);
  double last_x = 0, last_y = 0, largest_step = 0;
  for (int frame = 0; frame < 50000; ++frame) {
    if (frame == 20000) circle.radius = 25.0f;  // a sudden change of radius
    hal_manual::run_frames(1);
    const double x = circle.output_x.read_absolute(), y = circle.output_y.read_absolute();
    largest_step = fmax(largest_step, hypot(x - last_x, y - last_y));
    last_x = x;
    last_y = y;
  }
  // No jump: never more than the arc of the larger circle in one frame, r·ω·dt.
  EXPECT_LE(largest_step, 25.0 * 10.0 * kDt * 1.0001);
}

TEST_F(GeneratorsTest, WaveWithPhaseFollowsTheShiftedSineFromWhereItStarted) {
  WaveGenerator1D wave;
  ASSERT_EQ(wave.begin(), Status::kOk);
  wave.setNoInput();
  wave.amplitude = 3.0f;
  wave.phase = 0.7f;
  wave.frequency = 50.0f;  // rad/s
  ASSERT_EQ(dance_start(), Status::kOk);
  const double a = 3.0, phi = static_cast<double>(wave.phase), w = static_cast<double>(wave.frequency);
  for (int frame = 1; frame <= 20000; ++frame) {
    hal_manual::run_frames(1);
    if (frame % 997 != 0) continue;
    const double theta = w * frame * kDt;
    ASSERT_NEAR(wave.output.read_absolute(), a * sin(theta + phi) - a * sin(phi), 1e-9) << "frame " << frame;
  }
}

TEST_F(GeneratorsTest, SpatialWaveTakesItsAngleFromTheInputsTravel) {
  VelocityGenerator feed;
  WaveGenerator1D wave;
  ASSERT_EQ(feed.begin(), Status::kOk);
  ASSERT_EQ(wave.begin(), Status::kOk);
  feed.output.map(&wave.input);
  feed.speed_units_per_sec = 10.0f;  // mm/s along the line
  wave.amplitude = 1.0f;
  wave.frequency = static_cast<float>(2 * kPi / 5.0);  // one period every 5 mm
  ASSERT_EQ(dance_start(), Status::kOk);
  hal_manual::run_frames(25000);  // 1 s: 10 mm, two whole periods
  EXPECT_NEAR(wave.output.read_absolute(), 0.0, 1e-6);
  hal_manual::run_frames(3125);  // 1.25 mm more: a quarter period
  EXPECT_NEAR(wave.output.read_absolute(), 1.0, 1e-3);
}

TEST_F(GeneratorsTest, PathLengthOfAKnownPolylineTimesTheRatio) {
  PositionGenerator x, y;
  PathLengthGenerator2D extruder;
  ASSERT_EQ(x.begin(), Status::kOk);
  ASSERT_EQ(y.begin(), Status::kOk);
  x.output.map(&extruder.input_1);
  y.output.map(&extruder.input_2);
  extruder.set_ratio(0.5);
  ASSERT_EQ(extruder.begin(), Status::kOk);
  ASSERT_EQ(dance_start(), Status::kOk);
  // (0,0) → (30,0) → (30,40) → diagonal back to (0,0) at speeds in ratio 3:4: 30 + 40 + 50.
  x.go(30, ABSOLUTE, 30);
  hal_manual::run_frames(30000);
  y.go(40, ABSOLUTE, 40);
  hal_manual::run_frames(30000);
  x.go(0, ABSOLUTE, 30);
  y.go(0, ABSOLUTE, 40);
  hal_manual::run_frames(30000);
  EXPECT_NEAR(extruder.output.read_absolute(), 0.5 * (30 + 40 + 50), 1e-6);
}

TEST_F(GeneratorsTest, ThresholdCallbacksRunOncePerCrossingInTheLoop) {
  static int uppers = 0, lowers = 0;
  uppers = lowers = 0;
  PositionGenerator source;
  ThresholdGenerator limit;
  ASSERT_EQ(source.begin(), Status::kOk);
  ASSERT_EQ(limit.begin(), Status::kOk);
  source.output.map(&limit.input);
  limit.setUpperThreshold(5.0, true);
  limit.setLowerThreshold(-5.0);
  limit.setUpperCallback([] { ++uppers; });
  limit.setLowerCallback([] { ++lowers; });
  ASSERT_EQ(dance_start(), Status::kOk);
  source.go(8, ABSOLUTE, 100);
  hal_manual::run_frames(5000);  // crosses 5 once, stays beyond
  EXPECT_EQ(uppers, 0);          // not from the frame
  dance_loop();
  EXPECT_EQ(uppers, 1);
  EXPECT_DOUBLE_EQ(limit.output.read_absolute(), 5.0);  // clamped
  source.go(-8, ABSOLUTE, 100);
  hal_manual::run_frames(5000);
  dance_loop();
  dance_loop();
  EXPECT_EQ(lowers, 1);
  EXPECT_DOUBLE_EQ(limit.output.read_absolute(), -8.0);  // not clamped below
  EXPECT_EQ(uppers, 1);
}

TEST_F(GeneratorsTest, ScalingFiltersInBothModes) {
  PositionGenerator source;
  ScalingFilter1D incremental, absolute;
  ASSERT_EQ(source.begin(), Status::kOk);
  ASSERT_EQ(incremental.begin(INCREMENTAL), Status::kOk);
  ASSERT_EQ(absolute.begin(ABSOLUTE), Status::kOk);
  source.output.map(&incremental.input);
  incremental.output.map(&absolute.input);
  incremental.set_ratio(3, 2);
  absolute.set_ratio(-2);
  ASSERT_EQ(dance_start(), Status::kOk);
  source.go(4, ABSOLUTE, 100);
  hal_manual::run_frames(2000);
  EXPECT_NEAR(incremental.output.read_absolute(), 6.0, 1e-9);
  EXPECT_NEAR(absolute.output.read_absolute(), -12.0, 1e-9);
}

TEST_F(GeneratorsTest, DirectionOfTravelAndWholeHalfWavesPerMove) {
  PositionGenerator x, y;
  Vector2DToAngle direction;
  MoveDurationToFrequency half_waves;
  ASSERT_EQ(x.begin(), Status::kOk);
  ASSERT_EQ(y.begin(), Status::kOk);
  ASSERT_EQ(direction.begin(), Status::kOk);
  ASSERT_EQ(half_waves.begin(), Status::kOk);
  x.output.map(&direction.input_x);
  y.output.map(&direction.input_y);
  half_waves.target_frequency = 4.0f;
  ASSERT_EQ(dance_start(), Status::kOk);
  x.go(-10, ABSOLUTE, 30);
  y.go(10, ABSOLUTE, 30);
  hal_manual::run_frames(100);
  EXPECT_NEAR(direction.output_theta.read_absolute(), 3 * kPi / 4, 1e-9);
  hal_manual::run_frames(50000);  // stopped: the direction stays
  EXPECT_NEAR(direction.output_theta.read_absolute(), 3 * kPi / 4, 1e-9);
  half_waves.input_move_duration.reset(2.6);  // 2.6 s × 4 = 10.4 → 10 half-waves
  hal_manual::run_frames(1);
  EXPECT_EQ(half_waves.output_frequency.read_absolute(), 10.0);
}

TEST_F(GeneratorsTest, PerpendicularWaveAcrossTheDirectionOfTravel) {
  WaveGenerator2D wave;
  ASSERT_EQ(wave.begin(), Status::kOk);
  wave.amplitude = 2.0f;
  ASSERT_EQ(dance_start(), Status::kOk);
  wave.input_frequency.reset(3.0);  // three half-waves per move
  wave.input_theta.reset(kPi / 2);  // travelling along +y
  wave.input_t.reset(1.0 / 6.0);    // θ = π·3·(1/6) = π/2: the crest
  hal_manual::run_frames(1);
  EXPECT_NEAR(wave.output_x.read_absolute(), -2.0, 1e-9);  // offset along −x, across the travel
  EXPECT_NEAR(wave.output_y.read_absolute(), 0.0, 1e-9);
  wave.input_t.reset(1.0);  // the move's end: back on the line
  hal_manual::run_frames(1);
  EXPECT_NEAR(wave.output_x.read_absolute(), 0.0, 1e-9);
}

TEST_F(GeneratorsTest, AttractorPullsAtMostItsSpeedAndLandsOnTheTarget) {
  Attractor2D attractor;
  ASSERT_EQ(attractor.begin(), Status::kOk);
  ASSERT_EQ(dance_start(), Status::kOk);
  attractor.set_target(30, 40, ABSOLUTE, 100);  // 50 mm away at 100 mm/s: 0.5 s
  hal_manual::run_frames(6250);                 // 0.25 s: half way along the straight line
  EXPECT_NEAR(attractor.output_x.read_absolute(), 15.0, 1e-6);
  EXPECT_NEAR(attractor.output_y.read_absolute(), 20.0, 1e-6);
  hal_manual::run_frames(6260);
  EXPECT_NEAR(attractor.output_x.read_absolute(), 30.0, 1e-9);
  EXPECT_NEAR(attractor.output_y.read_absolute(), 40.0, 1e-9);
  attractor.set_target(-5, 0, INCREMENTAL, 100);  // relative to where it is
  hal_manual::run_frames(2000);
  EXPECT_NEAR(attractor.output_x.read_absolute(), 25.0, 1e-9);
}

TEST_F(GeneratorsTest, PolarToCartesianAndItsInverseForDeepReads) {
  KinematicsPolarToCartesian polar;
  ASSERT_EQ(polar.begin(50.0), Status::kOk);  // a lever of 50 mm
  ASSERT_EQ(dance_start(), Status::kOk);
  polar.input_angle.reset(kPi / 3);
  hal_manual::run_frames(1);
  EXPECT_NEAR(polar.output_x.read_absolute(), 25.0, 1e-9);
  EXPECT_NEAR(polar.output_y.read_absolute(), 25.0 * sqrt(3.0), 1e-9);
  EXPECT_NEAR(polar.input_angle.read_deep(), kPi / 3, 1e-9);
  EXPECT_NEAR(polar.input_radius.read_deep(), 50.0, 1e-9);
}

}  // namespace
}  // namespace stepdance

namespace stepdance {
namespace {

// The original pantograph example's linkage (mm, rad).
const FiveBarGeometry kPantograph{60, 145.75, 134, 169, 178.3, 28.82, 2.9019};

TEST(FiveBarGeometry, InverseThenForwardIsTheIdentityOverTheReachableWorkspace) {
  int reachable = 0;
  for (double a1 = -0.4; a1 <= 1.6; a1 += 0.05) {
    for (double a2 = 1.5; a2 <= 3.5; a2 += 0.05) {
      double x, y;
      if (!kPantograph.forward(a1, a2, x, y)) continue;  // the links do not close here
      double b1, b2;
      ASSERT_TRUE(kPantograph.inverse(x, y, b1, b2)) << a1 << "," << a2;
      double fx, fy;
      ASSERT_TRUE(kPantograph.forward(b1, b2, fx, fy));
      EXPECT_NEAR(fx, x, 1e-6);  // 1 µm
      EXPECT_NEAR(fy, y, 1e-6);
      ++reachable;
    }
  }
  EXPECT_GT(reachable, 100);
}

TEST(FiveBarGeometry, ForwardAgreesWithTheLinkLengths) {
  // Independent check: every link keeps its length in the pose forward() computes.
  const double a1 = 0.6, a2 = 2.4;
  double x, y;
  ASSERT_TRUE(kPantograph.forward(a1, a2, x, y));
  const double cx = 30 + 145.75 * cos(a1), cy = -145.75 * sin(a1);
  const double dx = -30 + 134 * cos(a2), dy = -134 * sin(a2);
  // E is 169 from C and 178.3 from D; T is 28.82 from E: search E on the C circle for |E − D| = 178.3.
  double best = 1e9;
  for (int i = 0; i < 3600000; ++i) {
    const double phi = 2 * kPi * i / 3600000;
    const double px = cx + 169 * cos(phi), py = cy + 169 * sin(phi);
    const double miss = fabs(hypot(px - dx, py - dy) - 178.3);
    const double tool = fabs(hypot(px - x, -py - y) - 28.82);  // tool y is mirrored
    best = fmin(best, miss + tool);
  }
  EXPECT_LT(best, 1e-3);
}

class FiveBarBlocksTest : public test_support::EngineFixture {};

TEST_F(FiveBarBlocksTest, UnreachablePosesHoldTheLastOutputAndAreCounted) {
  KinematicsFiveBarForward arm;
  ASSERT_EQ(arm.begin(60, 145.75, 134, 169, 178.3, 28.82, 2.9019), Status::kOk);
  ASSERT_EQ(dance_start(), Status::kOk);
  // The block keeps the original's float parameters.
  const FiveBarGeometry as_floats{60.0f, 145.75f, 134.0f, 169.0f, 178.3f, 28.82f, 2.9019f};
  arm.input_r.reset(0.6);
  arm.input_l.reset(2.4);
  hal_manual::run_frames(1);
  const double x = arm.output_x.read_absolute(), y = arm.output_y.read_absolute();
  double ex, ey;
  ASSERT_TRUE(as_floats.forward(0.6, 2.4, ex, ey));
  EXPECT_NEAR(x, ex, 1e-9);
  EXPECT_NEAR(y, ey, 1e-9);
  // A pose the links cannot close: the arm ends (C, D) closer than |L3 − L4| = 9.3 mm.
  double far_r = 0, far_l = 0;
  bool found = false;
  for (double a1 = 0; a1 < 6.28 && !found; a1 += 0.01) {
    for (double a2 = 0; a2 < 6.28 && !found; a2 += 0.01) {
      const double cx = 30 + 145.75 * cos(a1), cy = -145.75 * sin(a1);
      const double dx = -30 + 134 * cos(a2), dy = -134 * sin(a2);
      if (hypot(cx - dx, cy - dy) < 5.0) far_r = a1, far_l = a2, found = true;
    }
  }
  ASSERT_TRUE(found);
  arm.input_r.reset(far_r);
  arm.input_l.reset(far_l);
  hal_manual::run_frames(3);
  EXPECT_EQ(arm.unreachable_count(), 3u);
  EXPECT_EQ(arm.output_x.read_absolute(), x);  // held, never NaN
  EXPECT_EQ(arm.output_y.read_absolute(), y);
  EXPECT_EQ(warning_count(), 3u);
}

// With an acceleration limit a, the speed ramps by a·dt per frame: after n frames of the ramp the
// output has moved a·dt²·n(n+1)/2; once at speed v it moves v·dt per frame. Off by default.
TEST_F(GeneratorsTest, VelocityRampsToANewSpeedUnderItsAccelerationLimit) {
  VelocityGenerator velocity;
  ASSERT_EQ(velocity.begin(), Status::kOk);
  velocity.set_acceleration(100.0);  // units/s²: 10 units/s is reached in 0.1 s = 2500 frames
  velocity.speed_units_per_sec = 10.0f;
  ASSERT_EQ(dance_start(), Status::kOk);
  hal_manual::run_frames(2500);
  EXPECT_NEAR(velocity.current_speed(), 10.0, 1e-9);
  EXPECT_NEAR(velocity.output.read(ABSOLUTE), 100.0 * kDt * kDt * 2500 * 2501 / 2, 1e-9);  // 0.5002
  hal_manual::run_frames(2500);
  EXPECT_NEAR(velocity.output.read(ABSOLUTE), 100.0 * kDt * kDt * 2500 * 2501 / 2 + 10.0 * kDt * 2500, 1e-9);
  velocity.speed_units_per_sec = 0.0f;  // and down again over 0.1 s, not at once
  hal_manual::run_frames(1);
  EXPECT_NEAR(velocity.current_speed(), 10.0 - 100.0 * kDt, 1e-9);
}

TEST_F(GeneratorsTest, WithoutALimitTheSpeedStepsAtOnce) {
  VelocityGenerator velocity;
  ASSERT_EQ(velocity.begin(), Status::kOk);
  velocity.speed_units_per_sec = 10.0f;
  ASSERT_EQ(dance_start(), Status::kOk);
  hal_manual::run_frames(1);
  EXPECT_NEAR(velocity.output.read(ABSOLUTE), 10.0 * kDt, 1e-12);
}

TEST_F(GeneratorsTest, CircleSpeedRampsUnderItsAngularAccelerationLimit) {
  CircleGenerator circle;
  ASSERT_EQ(circle.begin(), Status::kOk);
  circle.setNoInput();
  circle.set_angular_acceleration(2 * kPi);  // rad/s²
  circle.rotational_speed_rev_per_sec = static_cast<float>(2 * kPi);
  ASSERT_EQ(dance_start(), Status::kOk);
  hal_manual::run_frames(1000);  // 40 ms into a 1 s ramp: θ = α·dt²·n(n+1)/2
  EXPECT_NEAR(circle.angle(), 2 * kPi * kDt * kDt * 1000 * 1001 / 2, 1e-9);
}

TEST(AngleSourceWrap, EveryAngleLandsInZeroToTwoPi) {
  constexpr double kTwoPi = AngleSource::kTwoPi;
  EXPECT_EQ(AngleSource::wrap(0.25), 0.25);
  EXPECT_EQ(AngleSource::wrap(kTwoPi + 0.5), fmod(kTwoPi + 0.5, kTwoPi));  // as exact as fmod
  EXPECT_EQ(AngleSource::wrap(-0.5), -0.5 + kTwoPi);
  EXPECT_EQ(AngleSource::wrap(kTwoPi), 0.0);
  EXPECT_EQ(AngleSource::wrap(-1e-20), 0.0);  // −1e−20 + 2π rounds to 2π: not in [0, 2π)
  EXPECT_EQ(AngleSource::wrap(5 * kTwoPi + 1), fmod(5 * kTwoPi + 1, kTwoPi));
  const double far_below = AngleSource::wrap(-7 * kTwoPi - 1);
  EXPECT_GE(far_below, 0.0);
  EXPECT_LT(far_below, kTwoPi);
  EXPECT_NEAR(far_below, kTwoPi - 1, 1e-12);
}

}  // namespace
}  // namespace stepdance
