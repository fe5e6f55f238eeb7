// PenTrace: stroke splitting, pen-up moves, lengths and polyline simplification.
#include <gtest/gtest.h>

#include <cmath>

#include "models/pen_trace.hpp"

namespace stepdance::sim {
namespace {

/// Records a straight move from `from` to `to` in `count` equal samples (excluding `from`).
void move(PenTrace& trace, PenPoint from, PenPoint to, int count, bool down) {
  for (int i = 1; i <= count; ++i) {
    const double f = static_cast<double>(i) / count;
    trace.record(PenPoint{from.x_mm + f * (to.x_mm - from.x_mm), from.y_mm + f * (to.y_mm - from.y_mm)}, down);
  }
}

double distance_to_segment(PenPoint p, PenPoint a, PenPoint b) {
  const double dx = b.x_mm - a.x_mm;
  const double dy = b.y_mm - a.y_mm;
  const double length2 = dx * dx + dy * dy;
  double f = length2 == 0 ? 0 : ((p.x_mm - a.x_mm) * dx + (p.y_mm - a.y_mm) * dy) / length2;
  f = std::fmax(0, std::fmin(1, f));
  return std::hypot(p.x_mm - (a.x_mm + f * dx), p.y_mm - (a.y_mm + f * dy));
}

TEST(PenTrace, AStraightRunCollapsesToItsEnds) {
  PenTrace trace;
  trace.record(PenPoint{0, 0}, true);
  move(trace, PenPoint{0, 0}, PenPoint{10, 0}, 800, true);
  ASSERT_EQ(trace.strokes().size(), 1u);
  EXPECT_EQ(trace.strokes()[0], (Polyline{{0, 0}, {10, 0}}));
  EXPECT_EQ(trace.moves(), 800u);
  EXPECT_NEAR(trace.pen_down_mm(), 10.0, 1e-9);
}

TEST(PenTrace, CorexyStairStepsCollapseToOneSegment) {
  // Alternate A and B steps at 80 steps/mm: (+0.00625, +0.00625) then (+0.00625, −0.00625).
  PenTrace trace;
  trace.record(PenPoint{0, 0}, true);
  for (int i = 1; i <= 1600; ++i) trace.record(PenPoint{i / 160.0, (i % 2) / 160.0}, true);
  EXPECT_EQ(trace.strokes()[0], (Polyline{{0, 0}, {10, 0}}));
}

TEST(PenTrace, CornersAreKept) {
  PenTrace trace;
  trace.record(PenPoint{0, 0}, true);
  move(trace, PenPoint{0, 0}, PenPoint{1, 0}, 10, true);
  move(trace, PenPoint{1, 0}, PenPoint{1, 1}, 10, true);
  move(trace, PenPoint{1, 1}, PenPoint{0, 1}, 10, true);
  EXPECT_EQ(trace.strokes()[0], (Polyline{{0, 0}, {1, 0}, {1, 1}, {0, 1}}));
}

TEST(PenTrace, AReversalIsKept) {
  PenTrace trace;
  for (double x : {0.0, 0.5, 1.0, 0.75, 0.5}) trace.record(PenPoint{x, 0}, true);
  EXPECT_EQ(trace.strokes()[0], (Polyline{{0, 0}, {1, 0}, {0.5, 0}}));
}

TEST(PenTrace, MovesWithinTheToleranceOfThePreviousPointCollapse) {
  PenTrace trace;
  for (PenPoint p : {PenPoint{0, 0}, PenPoint{0.004, 0}, PenPoint{0.004, 0.004}, PenPoint{1, 0}}) trace.record(p, true);
  EXPECT_EQ(trace.strokes()[0], (Polyline{{0, 0}, {1, 0}}));
}

TEST(PenTrace, ACircleKeepsEverySampleWithinTheTolerance) {
  PenTrace trace;
  constexpr int kSamples = 3600;
  std::vector<PenPoint> samples;
  for (int i = 0; i <= kSamples; ++i) {
    const double angle = 2 * 3.14159265358979323846 * i / kSamples;
    samples.push_back(PenPoint{10 * std::cos(angle), 10 * std::sin(angle)});
    trace.record(samples.back(), true);
  }
  const Polyline& line = trace.strokes()[0];
  EXPECT_LT(line.size(), 200u);
  EXPECT_GT(line.size(), 50u);
  for (const PenPoint& p : samples) {
    double nearest = 1e9;
    for (size_t i = 1; i < line.size(); ++i) nearest = std::fmin(nearest, distance_to_segment(p, line[i - 1], line[i]));
    ASSERT_LE(nearest, 0.01 + 1e-12);
  }
}

TEST(PenTrace, StrokesSplitOnPenUpAndDown) {
  PenTraceSettings settings;
  settings.record_pen_up = true;
  PenTrace trace(settings);
  trace.record(PenPoint{0, 0}, true);
  trace.record(PenPoint{1, 0}, true);
  trace.record(PenPoint{1, 0}, false);
  trace.record(PenPoint{2, 0}, false);
  trace.record(PenPoint{2, 0}, true);
  trace.record(PenPoint{3, 0}, true);
  ASSERT_EQ(trace.strokes().size(), 2u);
  EXPECT_EQ(trace.strokes()[0], (Polyline{{0, 0}, {1, 0}}));
  EXPECT_EQ(trace.strokes()[1], (Polyline{{2, 0}, {3, 0}}));
  ASSERT_EQ(trace.pen_up_moves().size(), 1u);
  EXPECT_EQ(trace.pen_up_moves()[0], (Polyline{{1, 0}, {2, 0}}));
  EXPECT_DOUBLE_EQ(trace.pen_down_mm(), 2.0);
  EXPECT_DOUBLE_EQ(trace.pen_up_mm(), 1.0);
}

TEST(PenTrace, AMoveBelongsToThePreviousPenState) {
  PenTrace trace;
  trace.record(PenPoint{0, 0}, false);
  trace.record(PenPoint{5, 0}, true);   // travelled up to (5, 0), then down
  trace.record(PenPoint{5, 5}, false);  // drew to (5, 5), then up
  ASSERT_EQ(trace.strokes().size(), 1u);
  EXPECT_EQ(trace.strokes()[0], (Polyline{{5, 0}, {5, 5}}));
  EXPECT_TRUE(trace.pen_up_moves().empty());
  EXPECT_DOUBLE_EQ(trace.pen_up_mm(), 5.0);
}

TEST(PenTrace, ADownUpWithoutMovingIsADot) {
  PenTrace trace;
  trace.record(PenPoint{3, 4}, false);
  trace.record(PenPoint{3, 4}, true);
  trace.record(PenPoint{3, 4}, false);
  ASSERT_EQ(trace.strokes().size(), 1u);
  EXPECT_EQ(trace.strokes()[0], (Polyline{{3, 4}}));
  EXPECT_EQ(trace.samples(), 3u);
  EXPECT_EQ(trace.moves(), 0u);
}

// A shade change keeps its vertex even where the path runs straight on, and the stroke's first
// stretch takes the first shade measured on it.
TEST(PenTrace, ShadeChangesKeepTheirVertexAndMarkIt) {
  PenTrace trace;
  trace.record(PenPoint{0, 0}, true);
  trace.record(PenPoint{1, 0}, true);
  trace.record(PenPoint{2, 0}, true, 0.05);  // first shade: from the stroke's start
  trace.record(PenPoint{3, 0}, true, 0.05);
  trace.record(PenPoint{4, 0}, true, 0.06);  // a change at (4, 0)
  trace.record(PenPoint{5, 0}, true, 0.06);
  trace.record(PenPoint{6, 0}, true, 0.06);
  ASSERT_EQ(trace.strokes().size(), 1u);
  EXPECT_EQ(trace.strokes()[0], (Polyline{{0, 0}, {4, 0}, {6, 0}}));
  ASSERT_EQ(trace.shade_marks().size(), 1u);
  const std::vector<ShadeMark>& marks = trace.shade_marks()[0];
  ASSERT_EQ(marks.size(), 2u);
  EXPECT_EQ(marks[0].from_point, 0u);
  EXPECT_EQ(marks[0].shade, 0.05);
  EXPECT_EQ(marks[1].from_point, 1u);
  EXPECT_EQ(marks[1].shade, 0.06);
}

TEST(PenTrace, UnshadedStrokesHaveNoMarksAndPenUpShadesAreIgnored) {
  PenTrace trace;
  trace.record(PenPoint{0, 0}, true);
  trace.record(PenPoint{1, 0}, true);
  trace.record(PenPoint{2, 0}, false, 0.05);
  trace.record(PenPoint{3, 0}, true);
  trace.record(PenPoint{4, 0}, true);
  ASSERT_EQ(trace.strokes().size(), 2u);
  ASSERT_EQ(trace.shade_marks().size(), 2u);
  EXPECT_TRUE(trace.shade_marks()[0].empty());
  EXPECT_TRUE(trace.shade_marks()[1].empty());
}

}  // namespace
}  // namespace stepdance::sim
