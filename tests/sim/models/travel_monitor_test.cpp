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
