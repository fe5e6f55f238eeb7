// Five-bar arm model: its forward geometry by hand and against the library's, its angles solved
// back, its encoders counting from the home pose.
#include "models/five_bar_arm.hpp"

#include <gtest/gtest.h>

#include <cmath>

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

TEST(FiveBarArm, CountsFollowTheStylusAlongItsPath) {
  FiveBarArmSettings settings;  // the original's pantograph, 40,000 counts a turn
  PenPoint home;
  ASSERT_TRUE(FiveBarArm(settings).stylus_for(settings.home_right_rad, settings.home_left_rad, home));
  // Home is folded near the base (10.1, 47.7): out onto the drawing side, then across.
  settings.path_mm = {{home.x_mm, home.y_mm + 60}, {home.x_mm + 30, home.y_mm + 60}};
  settings.speed_mm_per_s = 10;
  settings.start = from_seconds(1);
  const FiveBarArm arm(settings);
  EXPECT_EQ(arm.right_count_at(0), 0);
  EXPECT_EQ(arm.left_count_at(from_seconds(1)), 0);
  // 6 s after the start the stylus is at the first corner; 9 s after, at the end.
  const PenPoint corner = arm.stylus_at(from_seconds(7));
  EXPECT_NEAR(corner.x_mm, home.x_mm, 1e-9);
  EXPECT_NEAR(corner.y_mm, home.y_mm + 60, 1e-9);
  const PenPoint end = arm.stylus_at(from_seconds(10));
  EXPECT_NEAR(end.x_mm, home.x_mm + 30, 1e-9);
  // Turning the counts back into angles (they count down as an angle grows, as the original's
  // pantograph sketches assume by inverting both encoders) and running them forward lands within
  // a count's reach.
  for (const SimTime time : {from_seconds(2), from_seconds(4), from_seconds(7), from_seconds(8.5), from_seconds(10)}) {
    const double per_count = 2 * kPi / 40000;
    const double a1 = settings.home_right_rad - (arm.right_count_at(time) - 0.5) * per_count;
    const double a2 = settings.home_left_rad - (arm.left_count_at(time) - 0.5) * per_count;
    PenPoint seen;
    ASSERT_TRUE(arm.stylus_for(a1, a2, seen));
    const PenPoint truth = arm.stylus_at(time);
    EXPECT_LT(std::hypot(seen.x_mm - truth.x_mm, seen.y_mm - truth.y_mm), 0.05) << to_seconds(time);
  }
  EXPECT_EQ(arm.unsolved(), 0u);
}

}  // namespace
}  // namespace stepdance::sim
