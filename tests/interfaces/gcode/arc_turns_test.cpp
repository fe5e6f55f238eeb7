// G2/G3 with P: LinuxCNC's turn count. The sweeps below are worked out by hand from the geometry
// (start angle, end angle, direction, plus 2π per extra turn); LinuxCNC's own reading of P is
// checked against rs274 in rs274_conformance_test.cpp (conformance/turns.ngc).
#include <gtest/gtest.h>

#include <math.h>
#include <string.h>

#include <vector>

#include "stepdance/interfaces/gcode/gcode_interpreter.hpp"
#include "stepdance/interfaces/gcode/gcode_parser.hpp"

namespace stepdance::gcode {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Sink final : GcodeSink {
  std::vector<Motion> motions;
  std::vector<double> dwells_s;
  void on_motion(const Motion& motion) override { motions.push_back(motion); }
  void on_dwell(double seconds) override { dwells_s.push_back(seconds); }
};

class ArcTurns : public ::testing::Test {
 protected:
  GrblError run(const char* line) {
    GcodeBlock block;
    const GrblError syntax = parse_line(line, strlen(line), block);
    return syntax != GrblError::kOk ? syntax : interpreter.execute(block, sink);
  }
  GcodeInterpreter interpreter;
  Sink sink;
};

TEST_F(ArcTurns, FullCircleThreeTimesClockwise) {
  ASSERT_EQ(run("G17 G21 G90 F600 G2 X0 Y0 I5 J0 P3"), GrblError::kOk);
  ASSERT_EQ(sink.motions.size(), 1u);
  EXPECT_NEAR(sink.motions[0].sweep_rad, -3 * 2 * kPi, 1e-9);
  EXPECT_NEAR(sink.motions[0].radius_mm, 5.0, 1e-12);
}

TEST_F(ArcTurns, ThreeQuarterArcCounterClockwisePlusOneTurn) {
  // Centre (5, 0): the start (0, 0) is at angle π, the end (5, 5) at π/2; counter-clockwise
  // from π through 3π/2 and 2π to 5π/2 is three quarters of a turn.
  ASSERT_EQ(run("G17 G21 G90 F600 G3 X5 Y5 I5 J0 P2"), GrblError::kOk);
  EXPECT_NEAR(sink.motions.back().sweep_rad, 1.5 * kPi + 2 * kPi, 1e-9);
}

TEST_F(ArcTurns, RadiusFormTakesTurnsToo) {
  // R5 to (10, 0): a half circle either way; clockwise with P4 adds three turns.
  ASSERT_EQ(run("G17 G21 G90 F600 G2 X10 Y0 R5 P4"), GrblError::kOk);
  EXPECT_NEAR(sink.motions.back().sweep_rad, -kPi - 3 * 2 * kPi, 1e-9);
}

TEST_F(ArcTurns, ThousandTurnHelixInEveryPlane) {
  ASSERT_EQ(run("G17 G21 G90 F600 G2 X0 Y0 Z10 I5 J0 P1000"), GrblError::kOk);
  EXPECT_NEAR(sink.motions.back().sweep_rad, -1000 * 2 * kPi, 1e-6);
  EXPECT_EQ(sink.motions.back().end_mm[kAxisZ], 10.0);
  ASSERT_EQ(run("G18 G3 X0 Z10 Y20 K5 P1000"), GrblError::kOk);  // ZX plane: centre Z+5 from Z10
  EXPECT_NEAR(sink.motions.back().sweep_rad, 1000 * 2 * kPi, 1e-6);
  ASSERT_EQ(run("G19 G2 Y20 Z10 X5 J5 P2"), GrblError::kOk);
  EXPECT_NEAR(sink.motions.back().sweep_rad, -2 * 2 * kPi, 1e-9);
}

TEST_F(ArcTurns, PlainArcAndP1AreTheSame) {
  ASSERT_EQ(run("G17 G21 G90 F600 G2 X10 Y0 I5 J0"), GrblError::kOk);
  ASSERT_EQ(run("G0 X0 Y0"), GrblError::kOk);
  ASSERT_EQ(run("G2 X10 Y0 I5 J0 P1"), GrblError::kOk);
  EXPECT_EQ(sink.motions[0].sweep_rad, sink.motions[2].sweep_rad);
  EXPECT_NEAR(sink.motions[0].sweep_rad, -kPi, 1e-12);
}

TEST_F(ArcTurns, PThatIsNotAWholeNumberFromOneIsRefusedAndChangesNothing) {
  ASSERT_EQ(run("G17 G21 G90 G1 F600"), GrblError::kOk);
  EXPECT_EQ(run("G2 X0 Y0 I5 P1.5"), GrblError::kCommandNeedsInteger);
  EXPECT_EQ(run("G2 X0 Y0 I5 P0"), GrblError::kCommandNeedsInteger);
  EXPECT_EQ(run("G2 X0 Y0 I5 P-2"), GrblError::kNegativeValue);  // the parser's, as for any P
  EXPECT_TRUE(sink.motions.empty());
  EXPECT_EQ(interpreter.modal().motion, 10);  // the refused lines' G2 did not stick
}

TEST_F(ArcTurns, PStaysUnusedOnStraightMovesAsInGrbl) {
  EXPECT_EQ(run("G21 G90 G1 X5 F600 P3"), GrblError::kUnusedValueWords);
}

TEST_F(ArcTurns, DwellOnTheSameLineKeepsItsP) {
  ASSERT_EQ(run("G17 G21 G90 F600 G4 P0.5 G2 X10 Y0 I5 J0"), GrblError::kOk);
  ASSERT_EQ(sink.dwells_s.size(), 1u);
  EXPECT_EQ(sink.dwells_s[0], 0.5);
  EXPECT_NEAR(sink.motions.back().sweep_rad, -kPi, 1e-12);
}

}  // namespace
}  // namespace stepdance::gcode
