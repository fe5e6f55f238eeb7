// Five-bar arm model: its forward geometry by hand and against the library's, its angles solved
// back, its encoders counting from the home pose.
#include "models/five_bar_arm.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iterator>
#include <stdexcept>

#include "stepdance/motion/five_bar_geometry.hpp"

namespace stepdance::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;

// S = 60, all arms and links 100, no stylus extension, both arms straight down the drawing side
// (A = 90°): C = (30, −100), D = (−30, −100); the elbow lies on the midline, √(100² − 30²) beyond.
TEST(FiveBarArm, ForwardMatchesAHandWorkedPose) {
  FiveBarArmSettings settings;
  settings.s_mm = 60;
  settings.l1_mm = settings.l2_mm = settings.l3_mm = settings.l4_mm = 100;
  settings.l5_mm = 0;
  settings.home_right_rad = settings.home_left_rad = kPi / 2;
  const FiveBarArm arm(settings);
  PenPoint stylus;
  ASSERT_TRUE(arm.stylus_for(kPi / 2, kPi / 2, stylus));
  EXPECT_NEAR(stylus.x_mm, 0.0, 1e-12);
  EXPECT_NEAR(stylus.y_mm, 100 + std::sqrt(100.0 * 100 - 30 * 30), 1e-12);
  EXPECT_FALSE(arm.stylus_for(0, kPi, stylus));  // arms spread flat: the links cannot meet
}

// Two independent implementations of the original's pantograph geometry must agree.
TEST(FiveBarArm, ForwardAgreesWithTheLibrarysForwardOverTheWorkspace) {
  const FiveBarArm arm(FiveBarArmSettings{});
  const FiveBarArmSettings g;
  const FiveBarGeometry library{g.s_mm, g.l1_mm, g.l2_mm, g.l3_mm, g.l4_mm, g.l5_mm, g.a6_rad};
  int compared = 0;
  for (double a1 = -1.0; a1 <= 1.6; a1 += 0.1) {
    for (double a2 = 1.5; a2 <= 4.2; a2 += 0.1) {
      PenPoint ours;
      double x = 0, y = 0;
      const bool closes = arm.stylus_for(a1, a2, ours);
      if (closes != library.forward(a1, a2, x, y) || !closes) continue;
      EXPECT_NEAR(ours.x_mm, x, 1e-9) << a1 << ", " << a2;
      EXPECT_NEAR(ours.y_mm, y, 1e-9) << a1 << ", " << a2;
      ++compared;
    }
  }
  EXPECT_GT(compared, 200);
}

constexpr double kDegree = kPi / 180;

/// The joint angles the counts say (each within a count of the truth): a joint's counter holds
/// floor(home·cpr/2π) − floor(A·cpr/2π), so A lies in the count's slot, here its middle.
struct SeenAngles {
  double right, left;
};
SeenAngles seen_angles(const FiveBarArm& arm, const FiveBarArmSettings& settings, SimTime time) {
  const double per_count = 2 * kPi / (4.0 * settings.pulses_per_revolution);
  const auto slot = [per_count](double home, int64_t count) {
    return (std::floor(home / per_count) - static_cast<double>(count) + 0.5) * per_count;
  };
  return {slot(settings.home_right_rad, arm.right_count_at(time)),
          slot(settings.home_left_rad, arm.left_count_at(time))};
}

/// The hand rests 1 s at every point; the moment half-way through the rest at point `index`.
SimTime resting_at(const FiveBarArmSettings& settings, PenPoint home, size_t index) {
  double seconds = 0;
  PenPoint from = home;
  for (size_t i = 0; i <= index; ++i) {
    const PenPoint& to = settings.path_mm[i];
    seconds += std::hypot(to.x_mm - from.x_mm, to.y_mm - from.y_mm) / settings.speed_mm_per_s;
    seconds += i < index ? 1.0 : 0.5;
    from = to;
  }
  return settings.start + from_seconds(seconds);
}

// The original pantograph rests folded back against its stops (right −60°, left 240°); its left
// arm and link come in line (a dead point) before the arms can swing out over the paper. Every
// point of the hand's path is the stylus of a pose inside the stops, built with the forward map:
// two poses on the way in, the dead point with the left arm at 220°, three poses beyond it. Read
// every 100 µs, as a board's frames do, the joints must come back as those poses, within a count.
TEST(FiveBarArm, PathBuiltFromPosesInsideTheStopsComesBackAsThosePoses) {
  FiveBarArmSettings settings;
  const FiveBarArm geometry(settings);
  // The dead point: D = P_l + L2·(cos A2, −sin A2) and E in line beyond the pivot,
  // E = P_l + (L2 − L4)·(cos A2, −sin A2); C lies L1 from P_r and L3 from E, the solution inside
  // the right stop (the other is at −106°).
  const double left = 220 * kDegree;
  const double ex = -settings.s_mm / 2 + (settings.l2_mm - settings.l4_mm) * std::cos(left);
  const double ey = -(settings.l2_mm - settings.l4_mm) * std::sin(left);
  const double px = settings.s_mm / 2, span = std::hypot(ex - px, ey);
  const double along = (settings.l1_mm * settings.l1_mm - settings.l3_mm * settings.l3_mm + span * span) / (2 * span);
  const double across = std::sqrt(settings.l1_mm * settings.l1_mm - along * along);
  const double cx = px + (along * (ex - px) - across * ey) / span, cy = (along * ey + across * (ex - px)) / span;
  const double dead_right = std::atan2(-cy, cx - px);
  ASSERT_GT(dead_right, settings.right_min_rad);
  const SeenAngles poses[] = {
      {-40 * kDegree, 235 * kDegree}, {-20 * kDegree, 230 * kDegree}, {dead_right, left},
      {20 * kDegree, 200 * kDegree},  {20 * kDegree, 170 * kDegree},  {30 * kDegree, 150 * kDegree}};
  PenPoint home;
  ASSERT_TRUE(geometry.stylus_for(settings.home_right_rad, settings.home_left_rad, home));
  for (const SeenAngles& pose : poses) {
    PenPoint point;
    ASSERT_TRUE(geometry.stylus_for(pose.right, pose.left, point));
    settings.path_mm.push_back(point);
    settings.dwell_s.push_back(1.0);
  }
  settings.start = from_seconds(1);
  const FiveBarArm arm(settings);
  EXPECT_EQ(arm.right_count_at(0), 0);
  EXPECT_EQ(arm.left_count_at(from_seconds(1)), 0);
  const double per_count = 2 * kPi / 40000;
  SimTime time = from_seconds(1);
  for (size_t i = 0; i < std::size(poses); ++i) {
    const SimTime resting = resting_at(settings, home, i);
    for (; time < resting; time += 100 * kMicrosecond) arm.right_count_at(time);
    const SeenAngles seen = seen_angles(arm, settings, resting);
    EXPECT_NEAR(seen.right, poses[i].right, per_count) << "pose " << i;
    EXPECT_NEAR(seen.left, poses[i].left, per_count) << "pose " << i;
  }
  EXPECT_EQ(arm.unsolved(), 0u);
}

// A small symmetric arm (S = 60, arms and links 100, no extension) at rest with both arms
// straight down the drawing side (90°), each against its stop: the right may only grow, the left
// only shrink, so the arms may lean in but not spread. Home: the elbow at (0, 100 + √(100² − 30²)).
FiveBarArmSettings leaning_arm() {
  FiveBarArmSettings settings;
  settings.l1_mm = settings.l2_mm = settings.l3_mm = settings.l4_mm = 100;
  settings.l5_mm = 0;
  settings.home_right_rad = settings.home_left_rad = kPi / 2;
  settings.right_min_rad = settings.left_max_rad = kPi / 2;
  return settings;
}

// Pulling the stylus 5 mm in towards the pivots, to (0, 190.39): the right arm would have to
// turn to atan2(190.39, −30) − acos(|T − P_r|/200) = 83.5°, past its stop; the only pose inside
// the stops there has the arms crossed (114.4°, 65.6°), 24° away, no continuous move. The arm
// rests against its stops (counts 0) and those moments count as unsolved. Back home, it follows
// the hand out to (0, 197): A1 = atan2(197, −30) − acos(|T − P_r|/200), A2 = π − A1.
TEST(FiveBarArm, APositionReachableOnlyPastAStopIsUnsolvedAndTheArmRestsThere) {
  FiveBarArmSettings settings = leaning_arm();
  const double home_y = 100 + std::sqrt(100.0 * 100 - 30 * 30);
  settings.path_mm = {{0, home_y - 5}, {0, home_y}, {0, 197}};
  settings.dwell_s = {1, 1, 1};
  const FiveBarArm arm(settings);
  const PenPoint home{0, home_y};
  const SimTime pulled = resting_at(settings, home, 0);
  EXPECT_EQ(arm.right_count_at(pulled), 0);
  EXPECT_EQ(arm.left_count_at(pulled), 0);
  EXPECT_GT(arm.unsolved(), 0u);
  const uint64_t unsolved_while_pulled = arm.unsolved();
  const SimTime out = resting_at(settings, home, 2);
  const double expected_right = std::atan2(197.0, -30.0) - std::acos(std::hypot(30.0, 197.0) / 200);
  const SeenAngles seen = seen_angles(arm, settings, out);
  EXPECT_NEAR(seen.right, expected_right, 2 * kPi / 40000);
  EXPECT_NEAR(seen.left, kPi - expected_right, 2 * kPi / 40000);
  EXPECT_EQ(arm.unsolved(), unsolved_while_pulled);
}

// Stops that do not hold the home angles make no arm.
TEST(FiveBarArm, HomeMustLieInsideTheStops) {
  FiveBarArmSettings settings;
  settings.right_min_rad = -50 * kDegree;
  EXPECT_THROW(FiveBarArm{settings}, std::invalid_argument);
  settings = FiveBarArmSettings{};
  settings.left_max_rad = 230 * kDegree;
  EXPECT_THROW(FiveBarArm{settings}, std::invalid_argument);
}

}  // namespace
}  // namespace stepdance::sim
