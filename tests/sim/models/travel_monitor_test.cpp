// TravelMonitor: excursions outside the usable area are counted and remembered.
#include <gtest/gtest.h>

#include <cmath>

#include "models/travel_monitor.hpp"

namespace stepdance::sim {
namespace {

const TravelArea kAxidraw{0, 300, 0, 218};

TEST(TravelMonitor, EdgesAreInside) {
  TravelMonitor monitor(kAxidraw);
  for (PenPoint p : {PenPoint{0, 0}, PenPoint{300, 218}, PenPoint{150, 0}}) monitor.observe(0, p);
  EXPECT_EQ(monitor.excursion_count(), 0u);
  EXPECT_FALSE(monitor.outside());
}

TEST(TravelMonitor, RemembersEachExcursionWithItsFarthestPoint) {
  TravelMonitor monitor(kAxidraw);
  monitor.observe(0, PenPoint{10, 10});
  monitor.observe(1, PenPoint{-1, 5});
  monitor.observe(2, PenPoint{-3, 5});
  monitor.observe(3, PenPoint{-2, 220});  // hypot(2, 2) = 2.83 < 3
  monitor.observe(4, PenPoint{0, 218});
  monitor.observe(5, PenPoint{301, 0});
  EXPECT_EQ(monitor.excursion_count(), 2u);
  EXPECT_TRUE(monitor.outside());
  ASSERT_EQ(monitor.excursions().size(), 2u);
  const TravelExcursion& first = monitor.excursions()[0];
  EXPECT_EQ(first.start, 1);
  EXPECT_EQ(first.end, 4);
  EXPECT_EQ(first.first, (PenPoint{-1, 5}));
  EXPECT_EQ(first.farthest, (PenPoint{-3, 5}));
  EXPECT_DOUBLE_EQ(first.overshoot_mm, 3.0);
  EXPECT_EQ(monitor.excursions()[1].end, -1);
  EXPECT_DOUBLE_EQ(monitor.max_overshoot_mm(), 3.0);
  EXPECT_DOUBLE_EQ(monitor.overshoot_mm(PenPoint{-3, 222}), 5.0);
}

// A machine's own resolution: a position out by at most one microstep on each axis (the 1/80 mm
// of belt one AxiDraw motor step makes) is not an excursion; 0.1 mm out still is, and its
// overshoot is measured from the area itself.
TEST(TravelMonitor, ToleratesOneMicrostepOnEachAxis) {
  TravelArea area = kAxidraw;
  area.tolerance_mm = 1.0 / 80.0;
  TravelMonitor monitor(area);
  for (PenPoint p : {PenPoint{-1.0 / 80.0, 0}, PenPoint{-1.0 / 80.0, -1.0 / 80.0}, PenPoint{300 + 1.0 / 80.0, 10}}) {
    monitor.observe(0, p);
  }
  EXPECT_EQ(monitor.excursion_count(), 0u);
  EXPECT_FALSE(monitor.outside());
  monitor.observe(1, PenPoint{-0.1, 5});
  monitor.observe(2, PenPoint{5, 5});
  monitor.observe(3, PenPoint{5, 218 + 1.5 / 80.0});
  EXPECT_EQ(monitor.excursion_count(), 2u);
  ASSERT_EQ(monitor.excursions().size(), 2u);
  EXPECT_DOUBLE_EQ(monitor.excursions()[0].overshoot_mm, 0.1);
  EXPECT_NEAR(monitor.excursions()[1].overshoot_mm, 1.5 / 80.0, 1e-12);
}

TEST(TravelMonitor, CountsBeyondWhatItRemembers) {
  TravelMonitor monitor(kAxidraw, 1);
  for (int i = 0; i < 3; ++i) {
    monitor.observe(2 * i, PenPoint{-1, 0});
    monitor.observe(2 * i + 1, PenPoint{1, 0});
  }
  EXPECT_EQ(monitor.excursion_count(), 3u);
  ASSERT_EQ(monitor.excursions().size(), 1u);
  EXPECT_EQ(monitor.excursions()[0].end, 1);
}

}  // namespace
}  // namespace stepdance::sim
