// StrokeStream: strokes never lost, endpoints kept, only sub-0.05 mm steps merged, incremental parts.
#include <gtest/gtest.h>

#include <cmath>

#include "view/stroke_stream.hpp"

namespace stepdance::sim::view {
namespace {

/// The page's side: applies parts as the protocol says (keep `from` points, append the rest).
struct PageStrokes {
  std::vector<Polyline> strokes;
  void apply(const std::vector<StrokePart>& parts) {
    for (const StrokePart& part : parts) {
      if (strokes.size() <= part.index) strokes.resize(part.index + 1);
      Polyline& stroke = strokes[part.index];
      ASSERT_LE(part.from, stroke.size());
      stroke.resize(part.from);
      stroke.insert(stroke.end(), part.points.begin(), part.points.end());
    }
  }
};

/// A straight stroke along x of `count` points 1/50 mm (0.02 mm) apart.
Polyline fine_line(int count, double y_mm) {
  Polyline line;
  for (int i = 0; i < count; ++i) line.push_back({i / 50.0, y_mm});
  return line;
}

TEST(StrokeStream, MergesOnlyStepsBelowTheResolutionAndKeepsBothEnds) {
  // 61 points 0.02 mm apart (0 … 1.2 mm): a point is kept when 0.05 mm or more from the last
  // kept one, i.e. every third (0.06 mm); index 60 is a multiple of 3, so 21 points remain.
  const std::vector<Polyline> strokes{fine_line(61, 0), fine_line(2, 5)};
  StrokeStream stream;
  PageStrokes page;
  page.apply(stream.take(strokes, 100000));
  ASSERT_EQ(page.strokes.size(), 2u);
  ASSERT_EQ(page.strokes[0].size(), 21u);
  for (size_t k = 0; k < 21; ++k) EXPECT_DOUBLE_EQ(page.strokes[0][k].x_mm, static_cast<double>(3 * k) / 50.0);
  EXPECT_EQ(stream.strokes_done(), 1u);  // the last stroke may still grow
}

TEST(StrokeStream, AnEndCloserThanTheResolutionStillEndsTheStrokeExactly) {
  // 0, 0.02, 0.04, 0.06, 0.08 mm: kept 0 and 0.06; the end 0.08 is 0.02 mm from 0.06 and replaces it.
  const std::vector<Polyline> strokes{fine_line(5, 0), {{9, 9}}};
  StrokeStream stream;
  PageStrokes page;
  page.apply(stream.take(strokes, 100000));
  ASSERT_EQ(page.strokes[0].size(), 2u);
  EXPECT_EQ(page.strokes[0].front(), (PenPoint{0, 0}));
  EXPECT_EQ(page.strokes[0].back(), (PenPoint{0.08, 0}));
}

TEST(StrokeStream, NoStrokeIsLostHoweverSmall) {
  // 500 dots and two-point strokes far below the resolution: every one arrives, ends intact.
  std::vector<Polyline> strokes;
  for (int i = 0; i < 500; ++i) {
    if (i % 2 == 0) {
      strokes.push_back({{i * 0.001, 0}});
    } else {
      strokes.push_back({{i * 0.001, 0}, {i * 0.001 + 0.001, 0}});
    }
  }
  StrokeStream stream;
  PageStrokes page;
  for (int round = 0; round < 1000 && stream.strokes_done() + 1 < strokes.size(); ++round)
    page.apply(stream.take(strokes, 7));
  page.apply(stream.take(strokes, 7));
  ASSERT_EQ(page.strokes.size(), strokes.size());
  for (size_t i = 0; i < strokes.size(); ++i) {
    EXPECT_EQ(page.strokes[i].front(), strokes[i].front()) << i;
    EXPECT_EQ(page.strokes[i].back(), strokes[i].back()) << i;
    EXPECT_EQ(page.strokes[i].size(), strokes[i].size()) << i;  // 1 or 2 points: the ends
  }
}

TEST(StrokeStream, AGrowingStrokeWithAMovingHeadEndsAsTheWholeStrokeWouldBeSent) {
  // The pen draws a right angle 0→(10,0)→(10,10) in 1 mm steps; as in PenTrace the last point
  // moves while a segment stays straight, and a corner makes it final.
  std::vector<Polyline> growing{{{0, 0}}};
  StrokeStream stream;
  PageStrokes page;
  for (int i = 1; i <= 10; ++i) {
    growing[0].resize(1);
    growing[0].push_back({static_cast<double>(i), 0});
    page.apply(stream.take(growing, 3));
    EXPECT_EQ(page.strokes[0].back(), (PenPoint{static_cast<double>(i), 0}));
  }
  for (int j = 1; j <= 10; ++j) {
    growing[0].resize(2);
    growing[0].push_back({10, static_cast<double>(j)});
    page.apply(stream.take(growing, 3));
  }
  growing.push_back({{20, 20}});  // the pen lifted and came down elsewhere
  page.apply(stream.take(growing, 3));
  page.apply(stream.take(growing, 3));
  ASSERT_EQ(page.strokes.size(), 2u);
  EXPECT_EQ(page.strokes[0], (Polyline{{0, 0}, {10, 0}, {10, 10}}));
  EXPECT_EQ(page.strokes[1], (Polyline{{20, 20}}));
}

TEST(StrokeStream, SaysWhenAnUpdateLeftPointsForTheNext) {
  // Three strokes of 2 points 1 mm apart (nothing merged), 6 points in all, and a budget of 3:
  // the first take stops inside the second stroke (behind), the second sends the rest.
  const std::vector<Polyline> strokes{{{0, 0}, {1, 0}}, {{0, 1}, {1, 1}}, {{0, 2}, {1, 2}}};
  StrokeStream stream;
  PageStrokes page;
  page.apply(stream.take(strokes, 3));
  EXPECT_TRUE(stream.behind());
  page.apply(stream.take(strokes, 3));
  EXPECT_FALSE(stream.behind());
  EXPECT_EQ(page.strokes, strokes);
  // A budget used up exactly at the end of a finished stroke, with another one after it: behind.
  StrokeStream exact;
  exact.take(strokes, 2);
  EXPECT_TRUE(exact.behind());
  // Everything sent: not behind, however often asked.
  page.apply(stream.take(strokes, 3));
  EXPECT_FALSE(stream.behind());
}

TEST(StrokeStream, AShadeStartIsNeverMergedAndArrivesWithItsPoint) {
  // 0, 0.02, …, 0.2 mm (11 points): unshaded, every third is kept (0, 0.06, 0.12, 0.18) and the
  // end 0.2 replaces 0.18. A shade starting at 0.02 mm (index 1) keeps that point however close.
  const std::vector<Polyline> strokes{fine_line(11, 0), {{9, 9}}};
  const std::vector<std::vector<ShadeMark>> marks{{{0, 1.5}, {1, 2.5}}, {}};
  StrokeStream stream;
  const std::vector<StrokePart> parts = stream.take(strokes, marks, 100000);
  ASSERT_GE(parts.size(), 1u);
  const StrokePart& first = parts[0];
  ASSERT_EQ(first.shades.size(), 2u);
  EXPECT_EQ(first.shades[0].point, 0u);
  EXPECT_EQ(first.shades[0].shade, 1.5);
  EXPECT_EQ(first.points[first.shades[1].point], (PenPoint{0.02, 0}));
  EXPECT_EQ(first.shades[1].shade, 2.5);
  EXPECT_EQ(first.points.back(), (PenPoint{0.2, 0}));
}

TEST(StrokeStream, AFirstShadeMeasuredLateStillStartsTheStroke) {
  // PenTrace gives a stroke its first shade from point 0 once measured, after points were sent.
  std::vector<Polyline> strokes{{{0, 0}, {1, 0}, {2, 0}}};
  std::vector<std::vector<ShadeMark>> marks{{}};
  StrokeStream stream;
  PageStrokes page;
  const std::vector<StrokePart> before = stream.take(strokes, marks, 100);
  ASSERT_EQ(before.size(), 1u);
  EXPECT_TRUE(before[0].shades.empty());
  strokes[0].push_back({3, 0});
  marks[0].push_back({0, 7});
  const std::vector<StrokePart> after = stream.take(strokes, marks, 100);
  ASSERT_EQ(after.size(), 1u);
  ASSERT_EQ(after[0].shades.size(), 1u);
  EXPECT_EQ(after[0].shades[0].point, 0u);
  EXPECT_EQ(after[0].shades[0].shade, 7);
}

TEST(StrokeStream, NothingNewGivesNoParts) {
  std::vector<Polyline> strokes{{{1, 1}, {2, 2}}, {{3, 3}}};
  StrokeStream stream;
  stream.take(strokes, 100);
  // The pen down and still: the last stroke's head has not moved, so nothing is sent again (a
  // paused run's updates carry nothing).
  EXPECT_TRUE(stream.take(strokes, 100).empty());
  EXPECT_TRUE(stream.take(strokes, 100).empty());
  // The head moves: it is re-sent in its place (the page keeps 0 points of stroke 1).
  strokes[1][0] = {3, 4};
  const std::vector<StrokePart> moved = stream.take(strokes, 100);
  ASSERT_EQ(moved.size(), 1u);
  EXPECT_EQ(moved[0].index, 1u);
  EXPECT_EQ(moved[0].from, 0u);
  ASSERT_EQ(moved[0].points.size(), 1u);
  EXPECT_EQ(moved[0].points[0], (PenPoint{3, 4}));
}

}  // namespace
}  // namespace stepdance::sim::view
