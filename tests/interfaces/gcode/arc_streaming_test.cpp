// A 1,000-turn helical arc through GCodeInterface on the manual board: fed to the planner over
// many loop passes, never more than GCodeInterface::kArcChordsPerLoopPass chords in one; `ok`
// only once all of it is planned (as Grbl answers an arc); `?` answered meanwhile; a soft reset
// abandons the rest. Expected figures come from the helix's closed form: the chord count from
// the sagitta rule ceil(|sweep| / (2 acos(1 - tolerance / r))), the end point and the 1,000 turns
// of the tool round the axis from its path.
#include <gtest/gtest.h>

#include <math.h>

#include <string>

#include "hal_manual.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/interfaces/gcode/gcode_interface.hpp"
#include "support/engine_fixture.hpp"
#include "support/fake_byte_stream.hpp"

namespace stepdance {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadiusMm = 5.0;
constexpr double kToleranceMm = 0.1;  // $12: coarse, so the 1,000 turns run in few frames
constexpr double kTurns = 1000.0;
// From (10, 10, 0) clockwise round (15, 10), 1,000 whole turns, Z rising to 10.
constexpr const char* kHelix = "G2 X10 Y10 Z10 I5 J0 P1000 F600000\n";

int count(const std::string& text, const std::string& word) {
  int n = 0;
  for (size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++n;
  return n;
}

class ArcStreaming : public test_support::EngineFixture {
 protected:
  void SetUp() override {
    EngineFixture::SetUp();
    ASSERT_EQ(gcode.begin(&host), Status::kOk);
    // Fast axes and a wide junction deviation: the helix's chords (2 mm) pass in a few frames each.
    for (uint32_t axis = 0; axis < 3; ++axis) {
      gcode.settings().set_from_sketch(110 + axis, 600000);  // mm/min
      gcode.settings().set_from_sketch(120 + axis, 1e6);     // mm/s²
      gcode.settings().set_from_sketch(130 + axis, 200);     // mm of travel
    }
    gcode.interpolator().set_acceleration(1e6);  // the path's own limit (2,000 mm/s² by default)
    gcode.settings().set_from_sketch(11, 1.0);
    gcode.settings().set_from_sketch(12, kToleranceMm);
    gcode.settings().set_from_sketch(20, 1);  // soft limits: the arc's box is checked, not its chords
    ASSERT_EQ(dance_start(), Status::kOk);
    host.send("G21 G90 G17 G0 X10 Y10 Z0\n");
    for (int i = 0; i < 10000 && count(replies, "ok") < 1; ++i) frame_then_pass();
    ASSERT_EQ(count(replies, "ok"), 1) << replies;
    while (!gcode.interpolator().is_idle()) frame_then_pass();
  }
  /// One loop pass; returns the arc chords it handed to the planner.
  uint32_t pass() {
    const uint32_t before = gcode.arc_chords_queued();
    dance_loop();
    replies += host.take();
    return gcode.arc_chords_queued() - before;
  }
  void frame_then_pass() {
    hal_manual::run_frames(1);
    pass();
  }
  static uint32_t expected_chords() {
    return static_cast<uint32_t>(ceil(kTurns * 2.0 * kPi / (2.0 * acos(1.0 - kToleranceMm / kRadiusMm))));
  }

  test_support::FakeByteStream host;
  GCodeInterface gcode;
  std::string replies;
};

TEST_F(ArcStreaming, ThousandTurnHelixLandsOnItsClosedFormBoundedPerPass) {
  host.send(kHelix);
  uint32_t queued = 0, most_in_a_pass = 0, passes_feeding = 0;
  uint32_t queued_when_answered = 0;
  bool answered = false;
  double turned_rad = 0.0, previous_rad = atan2(0.0, -kRadiusMm);  // the start is at 180°
  double worst_off_radius = 0.0;
  long frames = 0;
  while (frames < 5'000'000 && !(answered && gcode.interpolator().is_idle())) {
    const uint32_t in_pass = pass();
    queued += in_pass;
    most_in_a_pass = in_pass > most_in_a_pass ? in_pass : most_in_a_pass;
    passes_feeding += in_pass > 0;
    if (!answered && count(replies, "ok") == 2) answered = true, queued_when_answered = queued;
    hal_manual::run_frames(1);
    ++frames;
    // The tool's angle round the helix axis, unwrapped: it must add up to 1,000 turns.
    const double dx = gcode.output_x.read_absolute() - 15.0, dy = gcode.output_y.read_absolute() - 10.0;
    const double now_rad = atan2(dy, dx);
    double step = now_rad - previous_rad;
    if (step > kPi) step -= 2.0 * kPi;
    if (step < -kPi) step += 2.0 * kPi;
    turned_rad += step;
    previous_rad = now_rad;
    worst_off_radius = fmax(worst_off_radius, kRadiusMm - hypot(dx, dy));  // chords cut inside
  }
  EXPECT_EQ(count(replies, "error"), 0) << replies;
  ASSERT_TRUE(answered) << replies << " queued " << queued << " of " << expected_chords() << " in " << frames
                        << " frames, turned " << turned_rad;
  EXPECT_EQ(queued, expected_chords());
  EXPECT_EQ(queued_when_answered, expected_chords()) << "the ok came before the whole arc was planned";
  EXPECT_EQ(most_in_a_pass, GCodeInterface::kArcChordsPerLoopPass);
  EXPECT_GE(passes_feeding, expected_chords() / GCodeInterface::kArcChordsPerLoopPass);
  EXPECT_EQ(gcode.output_x.read_absolute(), 10.0);
  EXPECT_EQ(gcode.output_y.read_absolute(), 10.0);
  EXPECT_EQ(gcode.output_z.read_absolute(), 10.0);
  EXPECT_NEAR(turned_rad, -kTurns * 2.0 * kPi, 1e-6);  // clockwise
  EXPECT_LE(worst_off_radius, kToleranceMm + 1e-9);
}

TEST_F(ArcStreaming, StatusIsAnsweredAndHoldWorksWhileTheArcIsBeingFed) {
  host.send(kHelix);
  for (int i = 0; i < 20; ++i) frame_then_pass();
  ASSERT_EQ(count(replies, "ok"), 1) << "the arc's ok came early: " << replies;
  host.send("?");
  pass();
  EXPECT_EQ(count(replies, "<Run|"), 1) << replies;
  host.send("!");
  for (int i = 0; i < 2000; ++i) frame_then_pass();
  host.send("?");
  pass();
  EXPECT_EQ(count(replies, "<Hold:0|"), 1) << replies;
  EXPECT_EQ(count(replies, "ok"), 1) << "still feeding: the planner is full and holding";
}

TEST_F(ArcStreaming, SoftResetAbandonsTheRestOfTheArc) {
  host.send(kHelix);
  for (int i = 0; i < 50; ++i) frame_then_pass();
  ASSERT_FALSE(gcode.interpolator().is_idle());
  replies.clear();
  host.send("\x18");
  pass();
  // As Grbl's mc_arc bails on the abort and gc_execute_line still returns STATUS_OK: the line
  // is answered once, before the welcome.
  EXPECT_EQ(count(replies, "ok"), 1) << replies;
  EXPECT_LT(replies.find("ok\r\n"), replies.find("Grbl 1.1")) << replies;
  EXPECT_EQ(count(replies, "Grbl 1.1"), 1) << replies;
  uint32_t queued_after_reset = 0;
  for (int i = 0; i < 20000; ++i) {
    hal_manual::run_frames(1);
    queued_after_reset += pass();
  }
  EXPECT_EQ(queued_after_reset, 0u);
  EXPECT_TRUE(gcode.interpolator().is_idle());
  EXPECT_EQ(count(replies, "ok"), 1) << replies;
}

TEST_F(ArcStreaming, SoftLimitsTakeTheBoxTheArcSweeps) {
  // From (5, 9.9), full circles round (5, 15): radius 5.1 reaches X -0.1, outside the travel
  // [0, 200] although both ends are inside; radius 5 (from (5, 10)) just touches X 0.
  replies.clear();
  host.send("G0 X5 Y9.9\nG2 X5 Y9.9 I0 J5.1 F6000\n");
  for (int i = 0; i < 20000; ++i) frame_then_pass();
  EXPECT_EQ(count(replies, "ok"), 1) << "the G2 line must be refused: " << replies;
  EXPECT_EQ(gcode.arc_chords_queued(), 0u);
  replies.clear();
  host.send("\x18");  // whichever way the refusal came (error:15, or Grbl's ALARM:2), start afresh
  pass();
  replies.clear();  // Grbl's ALARM:2 line is answered by the reset
  host.send("$X\nG0 X5 Y10\nG2 X5 Y10 I0 J5 F6000\n");
  for (int i = 0; i < 200000 && !(count(replies, "ok") == 3 && gcode.interpolator().is_idle()); ++i) frame_then_pass();
  EXPECT_EQ(count(replies, "ok"), 3) << replies;
  EXPECT_EQ(count(replies, "error"), 0) << replies;
  EXPECT_GT(gcode.arc_chords_queued(), 0u);
}

}  // namespace
}  // namespace stepdance
