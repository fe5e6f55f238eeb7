// A G-code line's one-way path: parser stage → interpreter stage → machine, answered once at its end.
#include <gtest/gtest.h>

#include <string.h>

#include <string>
#include <vector>

#include "stepdance/interfaces/gcode/gcode_interpreter_stage.hpp"
#include "stepdance/interfaces/gcode/gcode_parser_stage.hpp"

namespace stepdance::gcode {
namespace {

/// Records what reaches the end of the path, in order.
struct RecordingAnswer final : LineAnswer {
  std::vector<std::string> events;
  void refuse(GrblError error) override { events.push_back("refuse " + std::to_string(grbl_number(error))); }
  void exceed_travel() override { events.push_back("out of travel"); }
  void taken() override { events.push_back("taken"); }
};

/// A machine that logs the calls it gets and, when `defer` is set, keeps the line's answer until
/// the test says its planner has taken the line.
struct LoggingMachine final : GrblMachine {
  std::vector<std::string> calls;
  std::vector<Motion> motions;
  bool defer = false;
  LineAnswer* held = nullptr;

  void on_motion(const Motion& motion) override {
    motions.push_back(motion);
    calls.push_back("motion");
  }
  void on_dwell(double) override { calls.push_back("dwell"); }
  void take_line_end(LineAnswer& answer) override {
    calls.push_back("line end");
    if (defer) {
      held = &answer;
    } else {
      answer.taken();
    }
  }
  MotionState motion_state() override { return MotionState::kIdle; }
  bool hold_complete() override { return true; }
  void position_mm(double (&out)[kAxisCount]) override {
    for (double& value : out) value = 0.0;
  }
  double feed_now_mm_per_min() override { return 0.0; }
  uint16_t queue_slots_free() override { return 15; }
  uint16_t queue_slots_total() override { return 15; }
  bool ready_for_line() override { return true; }
  void feed_hold() override {}
  void cycle_start() override {}
  bool soft_reset() override { return false; }
  void jog(const Motion&) override {}
  void jog_cancel() override {}
  void set_overrides(uint8_t, uint8_t) override {}
  double steps_per_mm(int) override { return 80.0; }
};

class GcodeLinePath : public ::testing::Test {
 protected:
  void SetUp() override { interpreting.begin(machine, settings); }
  void send(const char* line) { parsing.take(line, strlen(line), answer); }

  LoggingMachine machine;
  GrblSettings settings;
  InterpreterStage interpreting;
  ParserStage parsing{interpreting};
  RecordingAnswer answer;
};

TEST_F(GcodeLinePath, AnAcceptedLineReachesTheMachineThenItsEndAndIsTakenOnce) {
  send("G1 X10 Y-5 F600");
  ASSERT_EQ(machine.calls, (std::vector<std::string>{"motion", "line end"}));
  EXPECT_DOUBLE_EQ(machine.motions[0].end_mm[kAxisX], 10.0);
  EXPECT_DOUBLE_EQ(machine.motions[0].end_mm[kAxisY], -5.0);
  EXPECT_DOUBLE_EQ(machine.motions[0].feed_mm_per_min, 600.0);
  EXPECT_EQ(answer.events, (std::vector<std::string>{"taken"}));
}

// Each stage that refuses answers the line itself and hands nothing on: a syntax error (the
// parser's, error:25), a semantic one (the interpreter's: no feed, error:22).
TEST_F(GcodeLinePath, ARefusedLineIsAnsweredWhereItStopsAndReachesNoMachine) {
  send("G1 X1 X2");
  send("G1 X10");
  EXPECT_EQ(answer.events, (std::vector<std::string>{"refuse 25", "refuse 22"}));
  EXPECT_TRUE(machine.calls.empty());
  EXPECT_DOUBLE_EQ(interpreting.interpreter().position_mm()[kAxisX], 0.0);
}

// With soft limits on ($22 then $20, travel $130 = 100 mm) a line leaving the travel is stopped
// before the machine hears of any of it: a G28 whose first leg (to X150) is outside, though its
// second (to the stored point, 0) is inside. A G28 inside (X+50, then 0) runs both legs.
TEST_F(GcodeLinePath, ALineOutOfTravelStopsBeforeTheMachineWithNothingChanged) {
  ASSERT_EQ(settings.write(22, 1.0), GrblError::kOk);
  ASSERT_EQ(settings.write(20, 1.0), GrblError::kOk);
  ASSERT_EQ(settings.write(130, 100.0), GrblError::kOk);
  send("G0 X150");
  send("G91 G28 X150");
  EXPECT_TRUE(machine.calls.empty());
  EXPECT_TRUE(interpreting.interpreter().modal().absolute);  // the refused G91 changed nothing
  send("G91 G28 X50");
  EXPECT_EQ(answer.events, (std::vector<std::string>{"out of travel", "out of travel", "taken"}));
  ASSERT_EQ(machine.motions.size(), 2u);
  EXPECT_DOUBLE_EQ(machine.motions[0].end_mm[kAxisX], 50.0);
  EXPECT_DOUBLE_EQ(machine.motions[1].end_mm[kAxisX], 0.0);
}

// The machine's planner answers when it has taken the line, not the stage that handed it on.
TEST_F(GcodeLinePath, TheMachineAnswersWhenItsPlannerHasTakenTheLine) {
  machine.defer = true;
  send("G2 X10 Y0 I5 J0 F300");
  EXPECT_TRUE(answer.events.empty());
  ASSERT_NE(machine.held, nullptr);
  machine.held->taken();
  EXPECT_EQ(answer.events, (std::vector<std::string>{"taken"}));
}

// `$C`: the state advances (X now 10) and nothing reaches the machine; a line without words (`%`)
// goes no further than the parser.
TEST_F(GcodeLinePath, CheckModeAndEmptyLinesAreAnsweredWithoutTheMachine) {
  interpreting.set_check_mode(true);
  send("G1 X10 F600");
  send("%");
  EXPECT_TRUE(machine.calls.empty());
  EXPECT_EQ(answer.events, (std::vector<std::string>{"taken", "taken"}));
  EXPECT_DOUBLE_EQ(interpreting.interpreter().position_mm()[kAxisX], 10.0);
}

}  // namespace
}  // namespace stepdance::gcode
