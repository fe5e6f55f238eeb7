// The Grbl link as a sender sees it: replies, realtime bytes, reports, jogging and back-pressure.
#include "stepdance/interfaces/gcode/grbl_protocol.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/fake_byte_stream.hpp"

namespace stepdance::gcode {
namespace {

using FakeStream = test_support::FakeByteStream;

/// A machine whose queue the test fills and drains by hand.
struct FakeMachine final : GrblMachine {
  std::vector<Motion> motions;
  std::vector<Motion> jogs;
  MotionState state = MotionState::kIdle;
  int holds = 0, resumes = 0, resets = 0, jog_cancels = 0;
  uint8_t feed_override = 100;
  uint16_t free_slots = 15;
  double position[kAxisCount] = {};

  void on_motion(const Motion& motion) override {
    motions.push_back(motion);
    --free_slots;
    state = MotionState::kRun;
  }
  void on_dwell(double) override {}
  MotionState motion_state() override { return state; }
  bool hold_complete() override { return true; }
  void position_mm(double (&out)[kAxisCount]) override {
    for (int i = 0; i < kAxisCount; ++i) out[i] = position[i];
  }
  double feed_now_mm_per_min() override { return state == MotionState::kRun ? 600.0 : 0.0; }
  uint16_t queue_slots_free() override { return free_slots; }
  uint16_t queue_slots_total() override { return 15; }
  bool ready_for_line() override { return free_slots >= 2; }
  void feed_hold() override {
    ++holds;
    state = MotionState::kHolding;
  }
  void cycle_start() override {
    ++resumes;
    state = MotionState::kRun;
  }
  bool soft_reset() override {
    ++resets;
    const bool moving = state != MotionState::kIdle;
    state = MotionState::kIdle;
    free_slots = 15;
    return moving;
  }
  void jog(const Motion& motion) override {
    jogs.push_back(motion);
    state = MotionState::kJog;
  }
  void jog_cancel() override {
    ++jog_cancels;
    state = MotionState::kIdle;
  }
  void set_overrides(uint8_t feed, uint8_t) override { feed_override = feed; }
  double steps_per_mm(int axis) override { return 40.0 + axis; }
};

class GrblLink : public ::testing::Test {
 protected:
  void SetUp() override {
    protocol.begin(stream, machine);
    stream.take();
  }
  std::string exchange(const std::string& text) {
    stream.send(text);
    for (int i = 0; i < 50; ++i) protocol.poll();
    return stream.take();
  }
  FakeStream stream;
  FakeMachine machine;
  GrblProtocol protocol;
};

TEST(GrblLinkStart, WelcomesLikeGrbl) {
  FakeStream stream;
  FakeMachine machine;
  GrblProtocol protocol;
  protocol.begin(stream, machine);
  EXPECT_EQ(stream.take(), "\r\nGrbl 1.1h ['$' for help]\r\n");
}

TEST_F(GrblLink, OkOnlyAfterValidationAndErrorNumbersOtherwise) {
  EXPECT_EQ(exchange("G1 X10 F600\n"), "ok\r\n");
  ASSERT_EQ(machine.motions.size(), 1u);
  EXPECT_DOUBLE_EQ(machine.motions[0].end_mm[kAxisX], 10.0);
  EXPECT_EQ(exchange("G1 X1 X2\n"), "error:25\r\n");
  EXPECT_EQ(exchange("G5\n"), "error:20\r\n");
  EXPECT_EQ(exchange("\n"), "ok\r\n");
  EXPECT_EQ(exchange("(comment only)\r\n"), "ok\r\n");
  EXPECT_EQ(machine.motions.size(), 1u);
}

TEST_F(GrblLink, CrLfCrAndLfEachEndOneLine) {
  EXPECT_EQ(exchange("G0 X1\r\nG0 X2\rG0 X3\n"), "ok\r\nok\r\nok\r\n");
  EXPECT_EQ(machine.motions.size(), 3u);
}

TEST_F(GrblLink, OverlongLineIsErrorElevenAndTheNextLineWorks) {
  std::string line = "G0 X1 ";
  while (line.size() < 300) line += "(padding)";
  EXPECT_EQ(exchange(line + "\nG0 X2\n"), "error:11\r\nok\r\n");
  ASSERT_EQ(machine.motions.size(), 1u);
  EXPECT_DOUBLE_EQ(machine.motions[0].end_mm[kAxisX], 2.0);
}

TEST_F(GrblLink, StatusIsAnsweredWhileTheQueueIsFull) {
  machine.free_slots = 1;  // not ready for another line
  stream.send("G1 X5 F100\n?");
  protocol.poll();
  const std::string reply = stream.take();
  EXPECT_EQ(reply.rfind("<Idle|MPos:0.000,0.000,0.000|Bf:1,", 0), 0u) << reply;
  EXPECT_TRUE(machine.motions.empty());
  machine.free_slots = 15;
  EXPECT_EQ(exchange(""), "ok\r\n");
}

TEST_F(GrblLink, RealtimeBytesPassAFullReceiveBufferAndNothingIsLost) {
  machine.free_slots = 1;  // no line executes: the 128-byte buffer fills up
  std::string lines;
  for (int i = 0; i < 8; ++i) lines += "G1 X" + std::to_string(10 + i) + " F1000.00\n";  // 8 × 16 bytes
  ASSERT_EQ(lines.size(), 128u);
  stream.send(lines + "?G1 X18\n");
  protocol.poll();
  const std::string reply = stream.take();
  EXPECT_EQ(reply.rfind("<Idle|MPos:0.000,0.000,0.000|Bf:1,0|", 0), 0u) << reply;
  // Everything still arrives in order once the machine takes lines again.
  machine.free_slots = 100;
  for (int i = 0; i < 20; ++i) protocol.poll();
  ASSERT_EQ(machine.motions.size(), 9u);
  for (int i = 0; i < 9; ++i) EXPECT_DOUBLE_EQ(machine.motions[i].end_mm[kAxisX], 10.0 + i);
}

TEST_F(GrblLink, SettingNumbersBeyondTheTableAreRefusedWithoutConversion) {
  // Found by fuzzing: a setting number too large for an integer was converted before the check.
  EXPECT_EQ(exchange("$111111111111=2\n"), "error:3\r\n");
  EXPECT_EQ(exchange("$-1=2\n"), "error:3\r\n");
  EXPECT_EQ(exchange("$1.5=2\n"), "error:3\r\n");
}

TEST_F(GrblLink, StatusReportFieldsFollowTheSettings) {
  exchange("G10 L2 P1 X5\n");
  machine.position[kAxisX] = 12.5;
  std::string report = exchange("?");
  EXPECT_EQ(report, "<Idle|MPos:12.500,0.000,0.000|Bf:15,128|FS:0,0|WCO:5.000,0.000,0.000|Ov:100,100,100>\r\n");
  exchange("$10=0\n");
  report = exchange("?");
  EXPECT_EQ(report, "<Idle|WPos:7.500,0.000,0.000|FS:0,0>\r\n");
}

TEST_F(GrblLink, FeedHoldResumeAndSoftResetWithAlarm) {
  exchange("G1 X50 F100\n");
  exchange("!");
  EXPECT_EQ(machine.holds, 1);
  exchange("~");
  EXPECT_EQ(machine.resumes, 1);
  const std::string reply = exchange(std::string(1, '\x18'));
  EXPECT_EQ(machine.resets, 1);
  EXPECT_EQ(reply, "ALARM:3\r\n\r\nGrbl 1.1h ['$' for help]\r\n[MSG:'$H'|'$X' to unlock]\r\n");
  EXPECT_EQ(exchange("G0 X1\n"), "error:9\r\n");
  EXPECT_EQ(exchange("$X\n"), "[MSG:Caution: Unlocked]\r\nok\r\n");
  EXPECT_EQ(exchange("G0 X1\n"), "ok\r\n");
}

TEST_F(GrblLink, FeedOverrideBytesClampBetweenTenAndTwoHundred) {
  for (int i = 0; i < 15; ++i) exchange("\x91");
  EXPECT_EQ(machine.feed_override, 200);
  exchange("\x90");
  for (int i = 0; i < 120; ++i) exchange("\x94");
  EXPECT_EQ(machine.feed_override, 10);
}

TEST_F(GrblLink, SettingsListReportsTheSketchStepsAndRefusesWritingThem) {
  const std::string listing = exchange("$$\n");
  EXPECT_NE(listing.find("$100=40.000\r\n$101=41.000\r\n$102=42.000\r\n"), std::string::npos) << listing;
  EXPECT_NE(listing.find("$132="), std::string::npos);
  EXPECT_EQ(listing.substr(listing.size() - 4), "ok\r\n");
  EXPECT_EQ(exchange("$100=80\n"), "[MSG:steps/mm are set by the sketch's channels]\r\nerror:3\r\n");
  EXPECT_EQ(exchange("$110=1234.5\n"), "ok\r\n");
  EXPECT_DOUBLE_EQ(protocol.settings().max_rate_mm_per_min(0), 1234.5);
  EXPECT_EQ(exchange("$10=1.5\n"), "error:23\r\n");
  EXPECT_EQ(exchange("$999=1\n"), "error:3\r\n");
  EXPECT_EQ(exchange("$Q\n"), "error:3\r\n");
}

TEST_F(GrblLink, ParserStateAndBuildInfo) {
  exchange("G91 G20 G1 F10\n");
  EXPECT_EQ(exchange("$G\n"), "[GC:G1 G54 G17 G20 G91 G94 M5 M9 T0 F10.0 S0]\r\nok\r\n");
  EXPECT_EQ(exchange("$I\n"), "[VER:1.1h.20190825:Stepdance]\r\n[OPT:,15,128]\r\nok\r\n");
}

TEST_F(GrblLink, JoggingLeavesTheParserModesAndCanBeCancelled) {
  EXPECT_EQ(exchange("$J=G91 X10 F500\n"), "ok\r\n");
  ASSERT_EQ(machine.jogs.size(), 1u);
  EXPECT_DOUBLE_EQ(machine.jogs[0].end_mm[kAxisX], 10.0);
  EXPECT_DOUBLE_EQ(machine.jogs[0].feed_mm_per_min, 500.0);
  EXPECT_TRUE(protocol.interpreter().modal().absolute);
  exchange("\x85");
  EXPECT_EQ(machine.jog_cancels, 1);
  EXPECT_EQ(exchange("$J=X10\n"), "error:22\r\n");
  EXPECT_EQ(exchange("$J=G2 X10 F100\n"), "error:16\r\n");
  EXPECT_EQ(exchange("$J=F100\n"), "error:16\r\n");
}

TEST_F(GrblLink, SoftLimitsRefuseMovesOutsideTravel) {
  exchange("$20=1\n$130=100\n");
  EXPECT_EQ(exchange("G0 X150\n"), "error:15\r\n");
  EXPECT_EQ(exchange("$J=X-1 F100\n"), "error:15\r\n");
  EXPECT_EQ(exchange("G0 X10 Y10\n"), "ok\r\n");
  // A half circle from (10,10) around (10,20) reaches x = 0 at most: allowed. From (10,30), a full
  // circle around (2,30) ends where it starts but passes x = 2 − 8 = −6: refused.
  EXPECT_EQ(exchange("G2 X10 Y30 I0 J10 F100\n"), "ok\r\n");
  EXPECT_EQ(exchange("G2 X10 Y30 I-8 J0\n"), "error:15\r\n");
  EXPECT_EQ(exchange("G2 X10 Y30 I-5 J0\n"), "ok\r\n");
}

TEST_F(GrblLink, CheckModeValidatesWithoutMoving) {
  EXPECT_EQ(exchange("$C\n"), "[MSG:Enabled]\r\nok\r\n");
  EXPECT_EQ(exchange("G1 X10 F100\n"), "ok\r\n");
  EXPECT_EQ(exchange("G1 Y\n"), "error:2\r\n");
  EXPECT_TRUE(machine.motions.empty());
}

TEST_F(GrblLink, RepliesWaitWhenTheHostDoesNotRead) {
  stream.write_room = 0;
  stream.send("G0 X1\nG0 X2\n$$\n");
  for (int i = 0; i < 10; ++i) protocol.poll();
  EXPECT_EQ(stream.take(), "");
  stream.write_room = 1 << 20;
  for (int i = 0; i < 10; ++i) protocol.poll();
  const std::string replies = stream.take();
  EXPECT_EQ(replies.rfind("ok\r\nok\r\n$0=10\r\n", 0), 0u) << replies;
  EXPECT_EQ(protocol.replies_dropped(), 0u);
}

}  // namespace
}  // namespace stepdance::gcode
