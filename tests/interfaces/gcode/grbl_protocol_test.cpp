// The Grbl link as a sender sees it: replies, realtime bytes, reports, jogging and back-pressure.
#include "stepdance/interfaces/gcode/grbl_protocol.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "stepdance/interfaces/gcode/grbl_settings_store.hpp"
#include "support/fake_byte_stream.hpp"
#include "support/memory_store.hpp"

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
  EXPECT_EQ(exchange("(comment only)\n"), "ok\r\n");
  EXPECT_EQ(machine.motions.size(), 1u);
}

// A slicer may put a fan or temperature code on a motion line. The motion runs (ends worked out by
// hand: absolute X10 Y5, then 2 mm more in X under G91) and the housekeeping code with its
// parameters is ignored; a command after such a code would be lost as its parameter, so that line
// is refused whole and nothing moves.
TEST_F(GrblLink, AMotionLineWithAHousekeepingCodeStillMoves) {
  EXPECT_EQ(exchange("G90 G1 X10 Y5 F600 M106 S255\n"), "ok\r\n");
  ASSERT_EQ(machine.motions.size(), 1u);
  EXPECT_DOUBLE_EQ(machine.motions[0].end_mm[kAxisX], 10.0);
  EXPECT_DOUBLE_EQ(machine.motions[0].end_mm[kAxisY], 5.0);
  EXPECT_EQ(exchange("G91 X2 M107\n"), "ok\r\n");
  ASSERT_EQ(machine.motions.size(), 2u);
  EXPECT_DOUBLE_EQ(machine.motions[1].end_mm[kAxisX], 12.0);
  EXPECT_DOUBLE_EQ(machine.motions[1].end_mm[kAxisY], 5.0);
  EXPECT_EQ(exchange("M104 S200 G1 X10\n"), "error:20\r\n");
  EXPECT_EQ(machine.motions.size(), 2u);
  // The fan's S255 is not the spindle's speed.
  EXPECT_EQ(exchange("$G\n"), "[GC:G1 G54 G17 G21 G91 G94 M5 M9 T0 F600 S0]\r\nok\r\n");
}

// Grbl 1.1's protocol loop ends a line at every CR and every LF and answers empty lines, so CR LF
// is two lines, the second empty: two `ok`.
TEST_F(GrblLink, EveryCrAndEveryLfEndsALineAndEmptyLinesAreAnswered) {
  EXPECT_EQ(exchange("G0 X1\r\nG0 X2\rG0 X3\n"), "ok\r\nok\r\nok\r\nok\r\n");
  EXPECT_EQ(machine.motions.size(), 3u);
  EXPECT_EQ(exchange("\r\n"), "ok\r\nok\r\n");
  // A CR, then (in another read, as 0.3 s later) an LF: each is a line and gets its `ok`.
  EXPECT_EQ(exchange("G0 X4\r"), "ok\r\n");
  EXPECT_EQ(exchange("\n"), "ok\r\n");
}

// Grbl 1.1's protocol loop throws away every byte up to a space while it assembles a line
// (protocol.c: "Throw away whitespace and control characters"), so a NUL in the middle of a line
// takes nothing after it with it. It keeps DEL, which its parser then refuses as not a letter.
TEST_F(GrblLink, ControlBytesInsideALineAreDroppedAndTheRestIsKept) {
  EXPECT_EQ(exchange(std::string("G0 X3\0 Y4\n", 11)), "ok\r\n");
  ASSERT_EQ(machine.motions.size(), 1u);
  EXPECT_DOUBLE_EQ(machine.motions[0].end_mm[kAxisX], 3.0);
  EXPECT_DOUBLE_EQ(machine.motions[0].end_mm[kAxisY], 4.0);
  EXPECT_EQ(exchange("G0\tX5\x01 Y\x1b"
                     "6\x02\n"),
            "ok\r\n");
  ASSERT_EQ(machine.motions.size(), 2u);
  EXPECT_DOUBLE_EQ(machine.motions[1].end_mm[kAxisX], 5.0);
  EXPECT_DOUBLE_EQ(machine.motions[1].end_mm[kAxisY], 6.0);
  EXPECT_EQ(exchange("G0 X7\x7f\n"), "error:1\r\n");
  EXPECT_EQ(machine.motions.size(), 2u);
}

// Dropped control bytes still take their place in the 128-byte receive buffer (a
// character-counting sender counts them), but not in the line: 150 NULs around a short command
// are no over-long line.
TEST_F(GrblLink, ControlBytesDoNotMakeALineOverlong) {
  EXPECT_EQ(exchange(std::string(150, '\0') + "G0 X8\n"), "ok\r\n");
  ASSERT_EQ(machine.motions.size(), 1u);
  EXPECT_DOUBLE_EQ(machine.motions[0].end_mm[kAxisX], 8.0);
}

// Grbl counts a line's characters after removing blanks and comments, into an 80-byte buffer
// with its NUL (LINE_BUFFER_SIZE): 79 fit, the 80th makes the line error:11.
TEST_F(GrblLink, LineLengthCountsCharactersWithoutBlanksAndComments) {
  std::string commented = "G0 X1 ";
  while (commented.size() < 300) commented += "(padding)";
  EXPECT_EQ(exchange(commented + "\n"), "ok\r\n");
  const std::string zeros(71, '0');
  const std::string fits = "G1F100X" + zeros + "1";  // 79 characters: X000…001
  ASSERT_EQ(fits.size(), 79u);
  EXPECT_EQ(exchange("G1 F100 X" + zeros + "1\n"), "ok\r\n");
  EXPECT_EQ(exchange("G1F100X0" + zeros + "1\nG0 X2\n"), "error:11\r\nok\r\n");
  ASSERT_EQ(machine.motions.size(), 3u);
  EXPECT_DOUBLE_EQ(machine.motions[2].end_mm[kAxisX], 2.0);
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
  EXPECT_EQ(exchange("$1.5=2\n"), "ok\r\n");  // Grbl truncates the number: `$1=2`
  EXPECT_DOUBLE_EQ(protocol.settings().value(1), 2.0);
}

TEST_F(GrblLink, StatusReportFieldsFollowTheSettings) {
  exchange("G10 L2 P1 X5\n");
  machine.position[kAxisX] = 12.5;
  std::string report = exchange("?");
  // The first report carries WCO; Ov follows in the next one (Grbl never sends both at once).
  EXPECT_EQ(report, "<Idle|MPos:12.500,0.000,0.000|Bf:15,128|FS:0,0|WCO:5.000,0.000,0.000>\r\n");
  exchange("$10=0\n");
  report = exchange("?");
  EXPECT_EQ(report, "<Idle|WPos:7.500,0.000,0.000|FS:0,0|Ov:100,100,100>\r\n");
}

TEST_F(GrblLink, WorkOffsetIsReportedPeriodicallyAndAtOnceWhenItChanges) {
  // Grbl 1.1 at rest: WCO every 10th report, Ov every 10th, never both in one report.
  std::vector<int> wco_reports, ov_reports;
  for (int i = 0; i < 25; ++i) {
    const std::string report = exchange("?");
    if (report.find("|WCO:0.000,0.000,0.000") != std::string::npos) wco_reports.push_back(i);
    if (report.find("|Ov:") != std::string::npos) ov_reports.push_back(i);
  }
  EXPECT_EQ(wco_reports, (std::vector<int>{0, 10, 20}));
  EXPECT_EQ(ov_reports, (std::vector<int>{1, 11, 21}));
  // A new offset (G92 here) shows in the very next report, whatever the count.
  exchange("G92 X-3\n");
  EXPECT_NE(exchange("?").find("|WCO:3.000,0.000,0.000"), std::string::npos);
  EXPECT_EQ(exchange("?").find("|WCO:"), std::string::npos);
  // While moving the refresh slows to every 30th report.
  machine.state = MotionState::kRun;
  int wco_while_running = 0;
  for (int i = 0; i < 60; ++i) wco_while_running += exchange("?").find("|WCO:") != std::string::npos;
  EXPECT_EQ(wco_while_running, 2);
}

TEST_F(GrblLink, HomingIsAClearErrorUntilTheMachineHasIt) {
  EXPECT_EQ(exchange("$H\n"), "error:5\r\n");  // $22 off: Grbl's "homing not enabled"
  EXPECT_EQ(exchange("$22=1\n$H\n"), "ok\r\n[MSG:Homing is not set up on this machine]\r\nerror:5\r\n");
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
  EXPECT_EQ(exchange("$10=1.5\n"), "ok\r\n");  // Grbl truncates an integer setting's value
  EXPECT_DOUBLE_EQ(protocol.settings().value(10), 1.0);
  EXPECT_EQ(exchange("$999=1\n"), "error:3\r\n");
  EXPECT_EQ(exchange("$Q\n"), "error:2\r\n");  // Grbl reads a setting number and finds none
}

TEST_F(GrblLink, ParserStateAndBuildInfo) {
  exchange("G91 G20 G1 F10\n");
  EXPECT_EQ(exchange("$G\n"), "[GC:G1 G54 G17 G20 G91 G94 M5 M9 T0 F10.0 S0]\r\nok\r\n");
  EXPECT_EQ(exchange("$I\n"), "[VER:1.1h.20190830:Stepdance]\r\n[OPT:,15,128]\r\nok\r\n");
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

TEST_F(GrblLink, SoftLimitsNeedHomingAsOnGrbl) {
  EXPECT_EQ(exchange("$20=1\n"), "error:10\r\n");
  EXPECT_EQ(exchange("$22=1\n$20=1\n"), "ok\r\nok\r\n");
  EXPECT_TRUE(protocol.settings().soft_limits());
  EXPECT_EQ(exchange("$22=0\n"), "ok\r\n");  // homing off turns soft limits off
  EXPECT_FALSE(protocol.settings().soft_limits());
}

// Grbl 1.1h's limits_soft_check: a moving machine comes to a controlled stop, the queue is
// dropped, ALARM:2 and "Reset to continue"; nothing is heard but Ctrl-X, which ends the
// critical-event loop: the line then gets its `ok` (gc_execute_line returns STATUS_OK) before
// the welcome, and the alarm holds until `$X`.
TEST_F(GrblLink, ATargetOutsideTravelRaisesAlarmTwoAndLocksUntilReset) {
  exchange("$22=1\n$20=1\n$130=100\n");
  EXPECT_EQ(exchange("G0 X10 Y10\n"), "ok\r\n");
  EXPECT_EQ(machine.state, MotionState::kRun);
  EXPECT_EQ(exchange("G0 X150\nG0 X20\n"), "ALARM:2\r\n[MSG:Reset to continue]\r\n");
  EXPECT_EQ(machine.holds, 1);
  EXPECT_EQ(machine.resets, 1);
  EXPECT_EQ(machine.motions.size(), 1u);  // neither the move nor the line after it
  EXPECT_EQ(exchange("?G0 X30\n$X\n~"), "");
  EXPECT_EQ(exchange("\x18"), "ok\r\n\r\nGrbl 1.1h ['$' for help]\r\n[MSG:'$H'|'$X' to unlock]\r\n");
  EXPECT_EQ(exchange("G0 X20\n"), "error:9\r\n");
  EXPECT_EQ(exchange("$X\n"), "[MSG:Caution: Unlocked]\r\nok\r\n");
  EXPECT_EQ(exchange("G0 X20\n"), "ok\r\n");
  EXPECT_EQ(machine.motions.size(), 2u);
}

TEST_F(GrblLink, SoftLimitsCheckArcsAndJogs) {
  exchange("$22=1\n$20=1\n$130=100\n");
  EXPECT_EQ(exchange("$J=X-1 F100\n"), "error:15\r\n");  // a jog is refused, no alarm
  EXPECT_EQ(exchange("G0 X10 Y10\n"), "ok\r\n");
  // A half circle from (10,10) around (10,20) reaches x = 0 at most: allowed. From (10,30), a full
  // circle around (2,30) ends where it starts but passes x = 2 − 8 = −6: the alarm.
  EXPECT_EQ(exchange("G2 X10 Y30 I0 J10 F100\n"), "ok\r\n");
  EXPECT_EQ(exchange("G2 X10 Y30 I-5 J0\n"), "ok\r\n");
  EXPECT_EQ(exchange("G2 X10 Y30 I-8 J0\n"), "ALARM:2\r\n[MSG:Reset to continue]\r\n");
  EXPECT_EQ(machine.motions.size(), 3u);
}

TEST_F(GrblLink, CheckModeValidatesWithoutMoving) {
  EXPECT_EQ(exchange("$C\n"), "[MSG:Enabled]\r\nok\r\n");
  EXPECT_EQ(exchange("G1 X10 F100\n"), "ok\r\n");
  EXPECT_EQ(exchange("G1 Y\n"), "error:2\r\n");
  EXPECT_TRUE(machine.motions.empty());
}

TEST_F(GrblLink, RepliesWaitWhenTheHostDoesNotRead) {
  stream.write_room = 0;
  stream.send("G10 L2 P1 X1\nG10 L2 P2 X2\n$$\n");  // no motion: `$$` is refused while running
  for (int i = 0; i < 10; ++i) protocol.poll();
  EXPECT_EQ(stream.take(), "");
  stream.write_room = 1 << 20;
  for (int i = 0; i < 10; ++i) protocol.poll();
  const std::string replies = stream.take();
  EXPECT_EQ(replies.rfind("ok\r\nok\r\n$0=10\r\n", 0), 0u) << replies;
  EXPECT_EQ(protocol.replies_dropped(), 0u);
}

/// A board with a settings store: each boot() starts a fresh link on the same store, as a reset
/// starts the firmware again with the EEPROM as it was.
class GrblStoredSettings : public ::testing::Test {
 protected:
  std::string boot() {
    protocol = std::make_unique<GrblProtocol>();
    protocol->begin(stream, machine, &store);
    return stream.take();
  }
  std::string exchange(const std::string& text) {
    stream.send(text);
    for (int i = 0; i < 50; ++i) protocol->poll();
    return stream.take();
  }
  bool lists(const std::string& setting) {
    return exchange("$$\n").find("\r\n" + setting + "\r\n") != std::string::npos;
  }
  FakeStream stream;
  FakeMachine machine;
  test_support::MemoryStore store;
  std::unique_ptr<GrblProtocol> protocol;
};

TEST_F(GrblStoredSettings, HostWritesSurviveAReboot) {
  EXPECT_EQ(boot(), "\r\nGrbl 1.1h ['$' for help]\r\n");  // erased store: no message
  EXPECT_EQ(exchange("$110=7200\n$122=50.5\n$22=1\n$20=1\n$13=1\n"), "ok\r\nok\r\nok\r\nok\r\nok\r\n");
  EXPECT_EQ(boot(), "\r\nGrbl 1.1h ['$' for help]\r\n");
  EXPECT_TRUE(lists("$110=7200.000"));
  EXPECT_TRUE(lists("$122=50.500"));
  EXPECT_TRUE(lists("$20=1"));
  EXPECT_TRUE(lists("$13=1"));
  EXPECT_TRUE(lists("$111=5000.000"));  // never written: Grbl's default
  EXPECT_TRUE(protocol->settings().soft_limits());
}

TEST_F(GrblStoredSettings, TheSketchDefaultYieldsToTheStoredValueUntilRestored) {
  boot();
  exchange("$110=7200\n");
  boot();
  protocol->settings().set_from_sketch(110, 6000);  // the sketch's setup() after begin()
  protocol->settings().set_from_sketch(111, 4000);
  EXPECT_TRUE(lists("$110=7200.000"));
  EXPECT_TRUE(lists("$111=4000.000"));
  EXPECT_EQ(exchange("$RST=$\n"), "[MSG:Restoring defaults]\r\nok\r\n\r\nGrbl 1.1h ['$' for help]\r\n");
  EXPECT_TRUE(lists("$110=6000.000"));
  boot();
  EXPECT_TRUE(lists("$110=5000.000"));  // a new boot before the sketch sets its default: Grbl's
}

TEST_F(GrblStoredSettings, ACorruptStoreFallsBackToDefaultsWithAMessage) {
  boot();
  exchange("$110=7200\n$120=640\n");
  store.bytes()[10] ^= 0x04;  // one bit of the first stored value
  EXPECT_EQ(boot(),
            "\r\nGrbl 1.1h ['$' for help]\r\n"
            "[MSG:Stored settings unreadable (bad checksum or data): defaults restored]\r\n");
  EXPECT_TRUE(lists("$110=5000.000"));
  EXPECT_TRUE(lists("$120=1000.000"));  // all or nothing: the intact entry is not applied either
  // The next write replaces the bad store.
  exchange("$111=3000\n");
  EXPECT_EQ(boot(), "\r\nGrbl 1.1h ['$' for help]\r\n");
  EXPECT_TRUE(lists("$111=3000.000"));
}

TEST_F(GrblStoredSettings, AStoreOfAnotherVersionFallsBackToDefaultsWithAMessage) {
  boot();
  exchange("$110=7200\n");
  std::vector<uint8_t>& bytes = store.bytes();
  bytes[4] = 0;  // version byte; re-sign the 6 + 9 bytes so only the version is wrong
  const uint16_t crc = crc16_ccitt(bytes.data(), 15);
  bytes[15] = static_cast<uint8_t>(crc & 0xFF);
  bytes[16] = static_cast<uint8_t>(crc >> 8);
  EXPECT_EQ(boot(),
            "\r\nGrbl 1.1h ['$' for help]\r\n"
            "[MSG:Stored settings are version 0, this firmware reads version 1: defaults restored]\r\n");
  EXPECT_TRUE(lists("$110=5000.000"));
}

TEST_F(GrblStoredSettings, AFailedSaveSaysTheSettingLastsOnlyUntilReset) {
  boot();
  store.refuse_writes = true;
  EXPECT_EQ(exchange("$110=7200\n"),
            "[MSG:Setting applies until reset: the settings store refused the write]\r\nok\r\n");
  EXPECT_DOUBLE_EQ(protocol->settings().max_rate_mm_per_min(0), 7200.0);
  boot();
  EXPECT_TRUE(lists("$110=5000.000"));
}

TEST_F(GrblStoredSettings, RestoringOffsetsClearsTheCoordinateSystems) {
  boot();
  exchange("G10 L2 P1 X5\n$110=7200\n");
  EXPECT_EQ(exchange("$RST=#\n"), "[MSG:Restoring defaults]\r\nok\r\n\r\nGrbl 1.1h ['$' for help]\r\n");
  EXPECT_EQ(exchange("$#\n").rfind("[G54:0.000,0.000,0.000]\r\n", 0), 0u);
  EXPECT_TRUE(lists("$110=7200.000"));  // settings untouched
  EXPECT_EQ(exchange("$RST=x\n"), "error:3\r\n");
}

}  // namespace
}  // namespace stepdance::gcode
