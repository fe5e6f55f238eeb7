// The simulated AxiDraw moves the way the real one does. The original library's AxiDraw sketches
// invert both channels so that +x runs from motor A towards motor B and +y away from the long
// axis, and its EBB emulation drives an EiBotBoard's positive steps through those inverted
// channels. So a planned +X move of a sketch that inverts both channels (examples/GCodeStepASketch,
// as the original's gcode_stepasketch) must move the pen +X on the page; a motor plugged in the
// other way round (`reversed = true`) must flip its half of the motion only.
#include "simulation_fixture.hpp"

namespace stepdance::sim::test {
namespace {

/// GCodeStepASketch on a plotter whose pen starts at (50, 50) mm, with socket B's motor plugged in
/// as given, and a sender that moves 10 mm along +X.
std::string plus_x_move_scenario(bool b_reversed) {
  return "duration_s = 2\n"
         "[[board]]\nname = \"driver\"\nsketch = \"" +
         source_path("examples/GCodeStepASketch/GCodeStepASketch.ino") +
         "\"\nmodule = \"driver\"\n"
         "sockets = { A = { device = \"stepper\" }, B = { device = \"stepper\", reversed = " +
         (b_reversed ? "true" : "false") +
         " }, C = { device = \"servo\" } }\n"
         "[machine]\ntype = \"corexy_plotter\"\nboard = \"driver\"\nstart_mm = [50, 50]\n"
         "[[host]]\nboard = \"driver\"\n"
         "[[host.step]]\nwait = \"^Grbl 1\\\\.1\"\ntimeout_s = 1\n"
         "[[host.step]]\nstream = \"G1 X10 F1200\\n\"\n"
         "[[host.step]]\nwait = \"^<Idle\\\\|\"\npoll = \"?\"\n";
}

struct Outcome {
  PenPoint pen;
  int64_t a_steps = 0;
  int64_t b_steps = 0;
  bool host_done = false;
};

Outcome run(bool b_reversed, const std::string& name) {
  const scenario::Scenario loaded =
      parse(plus_x_move_scenario(b_reversed), source_path("tests/sim/assembly/directions.toml"));
  auto simulation = create(loaded, name, false);
  Outcome outcome;
  if (simulation == nullptr) return outcome;
  simulation->finish();
  outcome.pen = simulation->machine()->pen_position();
  outcome.a_steps = simulation->stepper("driver", 'A')->position_steps();
  outcome.b_steps = simulation->stepper("driver", 'B')->position_steps();
  outcome.host_done = simulation->host_client("driver")->completed();
  return outcome;
}

TEST(MachineDirections, BothChannelsInvertedAPlannedPlusXMoveMovesThePenPlusX) {
  const Outcome outcome = run(false, "directions_normal");
  ASSERT_TRUE(outcome.host_done);
  // 10 mm at 80 microsteps per mm: the kinematics' a = b = +800, sent inverted (DIR low) and
  // counted −800 each; the pen is at start − (a + b) / 2 = 50 + 10 in x and unmoved in y.
  EXPECT_EQ(outcome.a_steps, -800);
  EXPECT_EQ(outcome.b_steps, -800);
  EXPECT_NEAR(outcome.pen.x_mm, 60.0, 1e-9);
  EXPECT_NEAR(outcome.pen.y_mm, 50.0, 1e-9);
}

TEST(MachineDirections, AReversedMotorFlipsThatMotorsContribution) {
  const Outcome outcome = run(true, "directions_reversed");
  ASSERT_TRUE(outcome.host_done);
  // The same DIR-low steps turn motor B the other way: b = +10 mm, a = −10 mm. The pen is at
  // x = 50 − (−10 + 10) / 2 = 50 and y = 50 − (−10 − 10) / 2 = 60: the move went along +y.
  EXPECT_EQ(outcome.a_steps, -800);
  EXPECT_EQ(outcome.b_steps, 800);
  EXPECT_NEAR(outcome.pen.x_mm, 50.0, 1e-9);
  EXPECT_NEAR(outcome.pen.y_mm, 60.0, 1e-9);
}

TEST(MachineDirections, ReversedIsRefusedOnAServoSocket) {
  const std::string text = "duration_s = 1\n[[board]]\nname = \"driver\"\nsketch = \"" +
                           source_path("examples/GCodeStepASketch/GCodeStepASketch.ino") +
                           "\"\nmodule = \"driver\"\nsockets = { C = { device = \"servo\", reversed = true } }\n";
  const scenario::LoadResult loaded = scenario::parse_scenario(text, source_path("tests/sim/assembly/directions.toml"));
  ASSERT_FALSE(loaded.ok());
  EXPECT_NE(loaded.error_text().find("'reversed' does not apply to a servo"), std::string::npos) << loaded.error_text();
}

}  // namespace
}  // namespace stepdance::sim::test
