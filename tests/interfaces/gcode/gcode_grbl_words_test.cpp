// Words where Grbl 1.1h's gcode.c decides: G43.1/G49 (dynamic tool length offset), G2/G3 without
// axis words, exponents, the line-number limit. Expected values from gcode.c, not from our output.
#include <gtest/gtest.h>

#include <math.h>
#include <string.h>

#include <vector>

#include "stepdance/interfaces/gcode/gcode_interpreter.hpp"
#include "stepdance/interfaces/gcode/gcode_parser.hpp"

namespace stepdance::gcode {
namespace {

struct Motions final : GcodeSink {
  std::vector<Motion> list;
  void on_motion(const Motion& motion) override { list.push_back(motion); }
  void on_dwell(double) override {}
};

class GrblWords : public ::testing::Test {
 protected:
  GrblError run(const char* line) {
    GcodeBlock block;
    const GrblError syntax = parse_line(line, strlen(line), block);
    if (syntax != GrblError::kOk) return syntax;
    return interpreter.execute(block, sink);
  }
  double last_z() const { return sink.list.back().end_mm[kAxisZ]; }
  GcodeInterpreter interpreter;
  Motions sink;
};

// gcode.c: the offset is added to absolute Z targets (not G91 moves, not G53) and to the work
// offset a status report shows; G49 clears it.
TEST_F(GrblWords, DynamicToolLengthOffsetShiftsAbsoluteZ) {
  ASSERT_EQ(run("G43.1 Z2"), GrblError::kOk);
  EXPECT_TRUE(sink.list.empty());  // an axis command of its own: no motion
  EXPECT_DOUBLE_EQ(interpreter.work_offset_mm(kAxisZ), 2.0);
  ASSERT_EQ(run("G0 Z0"), GrblError::kOk);
  EXPECT_DOUBLE_EQ(last_z(), 2.0);
  ASSERT_EQ(run("G91 G0 Z1"), GrblError::kOk);
  EXPECT_DOUBLE_EQ(last_z(), 3.0);
  ASSERT_EQ(run("G90 G53 G0 Z0"), GrblError::kOk);
  EXPECT_DOUBLE_EQ(last_z(), 0.0);
  ASSERT_EQ(run("G21 G43.1 Z-1.5"), GrblError::kOk);
  ASSERT_EQ(run("G0 Z0"), GrblError::kOk);
  EXPECT_DOUBLE_EQ(last_z(), -1.5);
  // G92 Z0 here makes the current position read 0 in work coordinates, the offset included.
  ASSERT_EQ(run("G92 Z0"), GrblError::kOk);
  EXPECT_DOUBLE_EQ(interpreter.work_offset_mm(kAxisZ), -1.5);
  ASSERT_EQ(run("G49"), GrblError::kOk);
  EXPECT_DOUBLE_EQ(interpreter.work_offset_mm(kAxisZ), 0.0);
  EXPECT_DOUBLE_EQ(interpreter.modal().tool_length_offset_mm, 0.0);
}

TEST_F(GrblWords, ToolLengthErrorsAreGrbls) {
  EXPECT_EQ(run("G43.1"), GrblError::kG43DynamicAxisError);        // 37: no Z
  EXPECT_EQ(run("G43.1 X1 Z1"), GrblError::kG43DynamicAxisError);  // 37: another axis
  EXPECT_EQ(run("G43.1 Z1 G0"), GrblError::kAxisCommandConflict);  // 24
  EXPECT_EQ(run("G49 G1 X1 F100"), GrblError::kAxisCommandConflict);
  EXPECT_EQ(run("G43.1 Z1 G92"), GrblError::kAxisCommandConflict);
  EXPECT_EQ(run("G43 Z1"), GrblError::kUnsupportedCommand);  // 20: G43 itself
  EXPECT_EQ(run("G43.2 Z1"), GrblError::kUnsupportedCommand);
  EXPECT_DOUBLE_EQ(interpreter.modal().tool_length_offset_mm, 0.0);
  EXPECT_TRUE(sink.list.empty());
}

// gcode.c checks "no axis words" (26) before "no axis words in plane" (32).
TEST_F(GrblWords, ArcWithoutAxisWordsIsErrorTwentySix) {
  EXPECT_EQ(run("G2 I5 F100"), GrblError::kNoAxisWords);
  EXPECT_EQ(run("G2 Z5 I5 F100"), GrblError::kNoInPlaneAxisWords);
  EXPECT_TRUE(sink.list.empty());
}

// gcode.c (offset form): once an in-plane offset is there, I, J and K are all marked used, so the
// out-of-plane word is accepted and ignored; the radius form leaves it unused (error:36).
TEST_F(GrblWords, OffsetFormIgnoresTheOutOfPlaneOffsetWord) {
  // The arc from (0, 0) round (5, 0) to (10, 0), clockwise: half a turn of radius 5, in G17 and,
  // after G18, in the ZX plane (centre (Z, X) = (0, 5) from the start at X 0).
  ASSERT_EQ(run("G2 X10 I5 K1 F100"), GrblError::kOk);
  ASSERT_EQ(run("G2 X0 I-5 J0 K0"), GrblError::kOk);
  ASSERT_EQ(run("G18 G2 X10 I5 J1"), GrblError::kOk);
  ASSERT_EQ(sink.list.size(), 3u);
  const double kPi = 3.14159265358979323846;
  const double expected_center_0[3] = {5.0, 5.0, 0.0};  // G17: X; G18: Z
  const double expected_center_1[3] = {0.0, 0.0, 5.0};  // G17: Y; G18: X
  const double expected_end_x[3] = {10.0, 0.0, 10.0};
  for (int i = 0; i < 3; ++i) {
    const Motion& arc = sink.list[static_cast<size_t>(i)];
    EXPECT_EQ(arc.kind, MotionKind::kArc);
    EXPECT_NEAR(arc.center_0_mm, expected_center_0[i], 1e-12);
    EXPECT_NEAR(arc.center_1_mm, expected_center_1[i], 1e-12);
    EXPECT_NEAR(arc.radius_mm, 5.0, 1e-12);
    EXPECT_NEAR(fabs(arc.sweep_rad), kPi, 1e-12);
    EXPECT_NEAR(arc.end_mm[kAxisX], expected_end_x[i], 1e-12);
    EXPECT_DOUBLE_EQ(arc.end_mm[kAxisZ], 0.0);
  }
  EXPECT_EQ(run("G17 G2 X0 R5 K1"), GrblError::kUnusedValueWords);    // 36: R leaves K unused
  EXPECT_EQ(run("G17 G2 X10 K1"), GrblError::kNoInPlaneOffsetWords);  // 35: no in-plane offset
}

// Grbl's read_float reads no exponent: `X1e1` is X1 and an E word, which Grbl does not know.
TEST_F(GrblWords, AnExponentIsRefusedAndASeparateEIsTheExtruder) {
  EXPECT_EQ(run("G1X1e1F100"), GrblError::kUnsupportedCommand);
  EXPECT_EQ(run("G1 X1E1 F100"), GrblError::kUnsupportedCommand);
  EXPECT_EQ(run("G1 X1.e-2 F100"), GrblError::kUnsupportedCommand);
  EXPECT_EQ(run("G1X1e"), GrblError::kBadNumberFormat);
  EXPECT_TRUE(sink.list.empty());
  ASSERT_EQ(run("G1 X1 E1 F100"), GrblError::kOk);
  EXPECT_DOUBLE_EQ(sink.list.back().end_mm[kAxisE], 1.0);
  ASSERT_EQ(run("G1 X2(comment)E2"), GrblError::kOk);
  EXPECT_DOUBLE_EQ(sink.list.back().end_mm[kAxisE], 2.0);
}

TEST_F(GrblWords, LineNumbersUpToGrblsMaximum) {
  EXPECT_EQ(run("N10000000 G0 X1"), GrblError::kOk);
  EXPECT_EQ(run("N10000001 G0 X1"), GrblError::kInvalidLineNumber);
}

}  // namespace
}  // namespace stepdance::gcode
