// Interpreter semantics: units, distance modes, offsets, arcs and refusals that change nothing.
#include "stepdance/interfaces/gcode/gcode_interpreter.hpp"

#include <gtest/gtest.h>

#include <math.h>
#include <string.h>

#include <vector>

#include "stepdance/interfaces/gcode/arc_geometry.hpp"
#include "stepdance/interfaces/gcode/gcode_parser.hpp"

namespace stepdance::gcode {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct RecordingSink final : GcodeSink {
  std::vector<Motion> motions;
  std::vector<double> dwells_s;
  std::vector<CommandCode> flow;
  std::vector<CommandCode> spindle;
  int coordinate_changes = 0;
  void on_motion(const Motion& motion) override { motions.push_back(motion); }
  void on_dwell(double seconds) override { dwells_s.push_back(seconds); }
  void on_spindle(CommandCode code, double) override { spindle.push_back(code); }
  void on_program_flow(CommandCode code) override { flow.push_back(code); }
  void on_coordinate_data_changed() override { ++coordinate_changes; }
};

class Interpreter : public ::testing::Test {
 protected:
  GrblError run(const char* line) {
    GcodeBlock block;
    const GrblError syntax = parse_line(line, strlen(line), block);
    if (syntax != GrblError::kOk) return syntax;
    return interpreter.execute(block, sink);
  }
  const Motion& last() const { return sink.motions.back(); }

  GcodeInterpreter interpreter;
  RecordingSink sink;
};

TEST_F(Interpreter, AbsoluteAndIncrementalMovesInMillimetresAndInches) {
  ASSERT_EQ(run("G0 X10 Y20"), GrblError::kOk);
  EXPECT_EQ(last().kind, MotionKind::kRapid);
  EXPECT_DOUBLE_EQ(last().end_mm[kAxisX], 10.0);
  ASSERT_EQ(run("G91 G1 X1 Y-2 F300"), GrblError::kOk);
  EXPECT_DOUBLE_EQ(last().end_mm[kAxisX], 11.0);
  EXPECT_DOUBLE_EQ(last().end_mm[kAxisY], 18.0);
  EXPECT_DOUBLE_EQ(last().feed_mm_per_min, 300.0);
  ASSERT_EQ(run("G20 G90 X1 F10"), GrblError::kOk);
  EXPECT_DOUBLE_EQ(last().end_mm[kAxisX], 25.4);
  EXPECT_DOUBLE_EQ(last().feed_mm_per_min, 254.0);
}

TEST_F(Interpreter, WorkOffsetsG54G92AndG53) {
  ASSERT_EQ(run("G10 L2 P2 X100 Y50"), GrblError::kOk);
  EXPECT_EQ(sink.coordinate_changes, 1);
  ASSERT_EQ(run("G55 G0 X1 Y1"), GrblError::kOk);
  EXPECT_DOUBLE_EQ(last().end_mm[kAxisX], 101.0);
  EXPECT_DOUBLE_EQ(last().end_mm[kAxisY], 51.0);
  ASSERT_EQ(run("G92 X0 Y0"), GrblError::kOk);  // here is now work zero
  ASSERT_EQ(run("G0 X5"), GrblError::kOk);
  EXPECT_DOUBLE_EQ(last().end_mm[kAxisX], 106.0);
  ASSERT_EQ(run("G53 G0 X0 Y0"), GrblError::kOk);
  EXPECT_DOUBLE_EQ(last().end_mm[kAxisX], 0.0);
  ASSERT_EQ(run("G92.1"), GrblError::kOk);
  ASSERT_EQ(run("G0 X0"), GrblError::kOk);
  EXPECT_DOUBLE_EQ(last().end_mm[kAxisX], 100.0);
  ASSERT_EQ(run("G10 L20 P0 X7"), GrblError::kOk);  // current position reads X7 in G55
  EXPECT_DOUBLE_EQ(interpreter.coordinate_data().system_offset_mm[1][kAxisX], 93.0);
}

TEST_F(Interpreter, G28GoesThroughTheIntermediatePointToTheStoredOne) {
  ASSERT_EQ(run("G0 X30 Y40 Z5"), GrblError::kOk);
  ASSERT_EQ(run("G28.1"), GrblError::kOk);
  ASSERT_EQ(run("G0 X0 Y0 Z0"), GrblError::kOk);
  sink.motions.clear();
  ASSERT_EQ(run("G28 Z10"), GrblError::kOk);
  ASSERT_EQ(sink.motions.size(), 2u);
  EXPECT_DOUBLE_EQ(sink.motions[0].end_mm[kAxisZ], 10.0);
  EXPECT_DOUBLE_EQ(sink.motions[1].end_mm[kAxisX], 30.0);
  EXPECT_DOUBLE_EQ(sink.motions[1].end_mm[kAxisY], 40.0);
  EXPECT_DOUBLE_EQ(sink.motions[1].end_mm[kAxisZ], 5.0);
}

TEST_F(Interpreter, QuarterArcIjkHasTheRightCentreAndSweep) {
  ASSERT_EQ(run("G0 X10 Y0"), GrblError::kOk);
  ASSERT_EQ(run("G3 X0 Y10 I-10 J0 F600"), GrblError::kOk);
  const Motion& arc = last();
  EXPECT_EQ(arc.kind, MotionKind::kArc);
  EXPECT_NEAR(arc.center_0_mm, 0.0, 1e-12);
  EXPECT_NEAR(arc.center_1_mm, 0.0, 1e-12);
  EXPECT_NEAR(arc.radius_mm, 10.0, 1e-12);
  EXPECT_NEAR(arc.sweep_rad, kPi / 2.0, 1e-12);
  ASSERT_EQ(run("G2 X10 Y0 I0 J-10"), GrblError::kOk);  // back clockwise: the long way? no, short
  EXPECT_NEAR(last().sweep_rad, -kPi / 2.0, 1e-12);
}

TEST_F(Interpreter, RadiusFormPicksTheShortOrLongArc) {
  ASSERT_EQ(run("G0 X0 Y0"), GrblError::kOk);
  ASSERT_EQ(run("G2 X10 Y0 R10 F100"), GrblError::kOk);
  // Chord 10, radius 10: centre 5√3 below the chord for a short clockwise arc, sweep 60°.
  EXPECT_NEAR(last().center_0_mm, 5.0, 1e-12);
  EXPECT_NEAR(last().center_1_mm, -5.0 * sqrt(3.0), 1e-12);
  EXPECT_NEAR(last().sweep_rad, -kPi / 3.0, 1e-12);
  ASSERT_EQ(run("G2 X0 Y0 R-10"), GrblError::kOk);
  EXPECT_NEAR(last().sweep_rad, -5.0 * kPi / 3.0, 1e-12);
  EXPECT_EQ(run("G2 X100 Y0 R10"), GrblError::kArcRadiusError);
  EXPECT_EQ(run("G2 X0 Y0 R10"), GrblError::kInvalidTarget);
}

TEST_F(Interpreter, FullCircleWhenIjkEndEqualsStart) {
  ASSERT_EQ(run("G0 X5 Y0"), GrblError::kOk);
  ASSERT_EQ(run("G2 X5 Y0 I-5 J0 F100"), GrblError::kOk);
  EXPECT_NEAR(last().sweep_rad, -2.0 * kPi, 1e-12);
}

TEST_F(Interpreter, ArcChordsStayWithinTolerance) {
  ASSERT_EQ(run("G0 X50 Y0"), GrblError::kOk);
  ASSERT_EQ(run("G3 X-50 Y0 I-50 J0 Z7 F100"), GrblError::kOk);
  const Motion arc = last();
  const double tolerance_mm = 0.002;
  ArcSegmenter segments(arc, tolerance_mm);
  // Independent count: a chord of angle a has sagitta r(1 − cos(a/2)); the half turn needs
  // ceil(π / a_max) chords with a_max = 2·acos(1 − tol/r).
  const double expected = ceil(kPi / (2.0 * acos(1.0 - tolerance_mm / 50.0)));
  EXPECT_EQ(segments.segment_count(), static_cast<uint32_t>(expected));
  double previous[kAxisCount] = {50.0, 0.0, 0.0, 0.0};
  for (uint32_t k = 1; k <= segments.segment_count(); ++k) {
    double point[kAxisCount];
    segments.point_mm(k, point);
    EXPECT_NEAR(hypot(point[0], point[1]), 50.0, 1e-9);
    const double mid_x = (previous[0] + point[0]) / 2.0;
    const double mid_y = (previous[1] + point[1]) / 2.0;
    EXPECT_LE(50.0 - hypot(mid_x, mid_y), tolerance_mm + 1e-12);
    for (int axis = 0; axis < kAxisCount; ++axis) previous[axis] = point[axis];
  }
  EXPECT_DOUBLE_EQ(previous[0], -50.0);
  EXPECT_DOUBLE_EQ(previous[2], 7.0);  // helix: Z arrives exactly
}

TEST_F(Interpreter, SemanticErrorsLeaveTheStateUntouched) {
  ASSERT_EQ(run("G0 X1 Y2"), GrblError::kOk);
  const size_t motions = sink.motions.size();
  EXPECT_EQ(run("G1 X5"), GrblError::kUndefinedFeedRate);
  EXPECT_EQ(run("G20 G1 X5"), GrblError::kUndefinedFeedRate);
  EXPECT_FALSE(interpreter.modal().inches);  // G20 of the refused line did not stick
  EXPECT_EQ(run("G0 X5 P3"), GrblError::kUnusedValueWords);
  EXPECT_EQ(run("G80 X5"), GrblError::kAxisWordsUnused);
  EXPECT_EQ(run("G92 G1 X5 F10"), GrblError::kAxisCommandConflict);
  EXPECT_EQ(run("G53 G2 X5 Y5 R9 F10"), GrblError::kG53NeedsG0OrG1);
  EXPECT_EQ(run("G4"), GrblError::kValueWordMissing);
  EXPECT_EQ(run("G10 L2 X1"), GrblError::kValueWordMissing);
  EXPECT_EQ(run("G10 L2 P7 X1"), GrblError::kUnsupportedCoordinateSystem);
  EXPECT_EQ(run("G92"), GrblError::kNoAxisWords);
  EXPECT_EQ(run("G2 Z5 I1 F10"), GrblError::kNoInPlaneAxisWords);
  EXPECT_EQ(run("G2 X5 F10"), GrblError::kNoInPlaneOffsetWords);
  EXPECT_EQ(run("G2 X10 Y0 I30 J0 F10"), GrblError::kInvalidTarget);
  EXPECT_EQ(run("G93 G1 X3"), GrblError::kUndefinedFeedRate);
  EXPECT_EQ(sink.motions.size(), motions);
  EXPECT_DOUBLE_EQ(interpreter.position_mm()[kAxisX], 1.0);
  EXPECT_EQ(interpreter.modal().motion, 0);
}

TEST_F(Interpreter, InverseTimeGivesTheMoveDuration) {
  ASSERT_EQ(run("G93 G1 X10 F2"), GrblError::kOk);  // F2: the move takes half a minute
  EXPECT_DOUBLE_EQ(last().duration_min, 0.5);
  EXPECT_DOUBLE_EQ(last().feed_mm_per_min, 0.0);
  EXPECT_EQ(run("G94 G1 X20"), GrblError::kUndefinedFeedRate);  // leaving G93 forgets F
}

TEST_F(Interpreter, DwellSpindleAndProgramEndInOrder) {
  ASSERT_EQ(run("M3 S1000 G4 P0.5"), GrblError::kOk);
  ASSERT_EQ(sink.spindle.size(), 1u);
  EXPECT_EQ(sink.spindle[0], 30);
  ASSERT_EQ(sink.dwells_s.size(), 1u);
  EXPECT_DOUBLE_EQ(sink.dwells_s[0], 0.5);
  ASSERT_EQ(run("G91 G55 M30"), GrblError::kOk);
  ASSERT_EQ(sink.flow.size(), 1u);
  EXPECT_TRUE(interpreter.modal().absolute);  // program end restores G90 and G54
  EXPECT_EQ(interpreter.modal().coordinate_system, 0);
}

TEST_F(Interpreter, ExtruderFollowsM82AndM83AndG92E) {
  ASSERT_EQ(run("M83"), GrblError::kOk);
  ASSERT_EQ(run("G1 X1 E0.5 F100"), GrblError::kOk);
  ASSERT_EQ(run("G1 X2 E0.5"), GrblError::kOk);
  EXPECT_DOUBLE_EQ(last().end_mm[kAxisE], 1.0);
  ASSERT_EQ(run("M82"), GrblError::kOk);
  ASSERT_EQ(run("G92 E0"), GrblError::kOk);
  ASSERT_EQ(run("G1 X3 E2"), GrblError::kOk);
  EXPECT_DOUBLE_EQ(last().end_mm[kAxisE], 3.0);
}

}  // namespace
}  // namespace stepdance::gcode
