// EbbCommands on its own, over real replies, queue and pen but no link and no engine: each
// command's parameters, reply and effect. Rates and step counts from ebb-protocol.md's rules
// (SM: constant rate over Duration; XM: motor1 = A + B, motor2 = A − B; 25 ticks per ms).
#include <gtest/gtest.h>

#include <string.h>

#include <string>

#include "stepdance/core/fault.hpp"
#include "stepdance/interfaces/ebb/ebb_commands.hpp"
#include "support/engine_fixture.hpp"
#include "support/fake_byte_stream.hpp"

namespace stepdance::ebb {
namespace {

class EbbCommandsTest : public test_support::EngineFixture {
 protected:
  void SetUp() override {
    EngineFixture::SetUp();
    queue.begin(pen.up_position());
  }
  /// Runs one command line (name folded to upper case as the link does) and returns its reply;
  /// "(waits)" when it found the queue full.
  std::string run(const char* line) {
    char name[3] = {};
    size_t length = 0;
    for (; length < 2 && line[length] != '\0' && line[length] != ','; ++length) name[length] = line[length];
    replies.set_command(name);
    EbbParameters parameters(line + length, strlen(line) - length);
    if (!commands.execute(name, parameters)) return "(waits)";
    replies.flush(link);
    return link.take();
  }
  void frames(int count) {
    for (int i = 0; i < count; ++i) queue.run_frame(40);
  }
  int64_t motor(int index) const { return queue.executor().position_sixteenths(index); }

  EbbReplies replies;
  EbbMotionQueue queue;
  EbbPen pen;
  EbbCommands commands{replies, queue, pen};
  test_support::FakeByteStream link;
};

// SM,1000,100: 100 steps over 1000 ms = 25 000 ticks at ⌈100 · 2^31 / 25000⌉ per tick.
TEST_F(EbbCommandsTest, SmQueuesAConstantRateMoveAndWaitsWhenTheFifoIsFull) {
  EXPECT_EQ(run("SM,1000,100"), "OK\r\n");
  EXPECT_EQ(run("SM,1000,0,7"), "(waits)");  // depth 1: not answered, not queued
  EXPECT_EQ(queue.waiting(), 1u);
  frames(1);
  EXPECT_EQ(queue.executor().move().rate[0], 8589935);  // ⌈8589934.592⌉
  frames(25000 - 1);
  EXPECT_EQ(motor(0), 100);
  EXPECT_EQ(run("SM,1000,0,7"), "OK\r\n");
}

TEST_F(EbbCommandsTest, XmMixesTheAxesAndRefusesARateTooHigh) {
  EXPECT_EQ(run("XM,1000,30,10"), "OK\r\n");
  frames(25001);
  EXPECT_EQ(motor(0), 40);  // A + B
  EXPECT_EQ(motor(1), 20);  // A − B
  // 1 ms is 25 ticks; 100 steps in 25 ticks is 100 000 steps/s, over the EBB's 25 000.
  EXPECT_EQ(run("XM,1,100,0"), "!0 Err: <axis1> step rate too high\r\n");
  EXPECT_EQ(queue.waiting(), 0u);
  // SM clamps instead: one step a tick, 100 ticks.
  EXPECT_EQ(run("SM,1,100,0"), "OK\r\n");
  frames(100);
  EXPECT_EQ(motor(0), 140);
}

TEST_F(EbbCommandsTest, BadParametersAndUnknownCommandsGetTheirErrorsAndQueueNothing) {
  EXPECT_EQ(run("SM,0,10"), "!6 Err: Invalid parameter value\r\n");  // Duration 0 is invalid
  EXPECT_EQ(run("SM"), "!4 Err: Missing parameter(s)\r\n");
  EXPECT_EQ(run("QP,1"), "!7 Err: Extra parameter\r\n");  // QP takes none
  EXPECT_EQ(run("ZZ"), "!8 Err: Unknown command 'ZZ:5A5A'\r\n");
  EXPECT_EQ(queue.waiting(), 0u);
  EXPECT_EQ(replies.errors(), 4u);
}

TEST_F(EbbCommandsTest, AnAlarmRefusesMotorMovesButNotThePen) {
  report_fault(FaultLevel::kAlarm, FaultReason::kLimitHit, "test");
  EXPECT_EQ(run("SM,100,10"), "!9 Err: Alarm raised: motor moves refused until it is cleared\r\n");
  EXPECT_EQ(run("SP,0"), "OK\r\n");
  EXPECT_EQ(queue.waiting(), 1u);
}

TEST_F(EbbCommandsTest, PenCommandsUseThePensPositionsAndTpTogglesTheCommandedState) {
  EXPECT_EQ(run("SC,5,17000"), "OK\r\n");
  EXPECT_EQ(run("SP,0"), "OK\r\n");
  frames(1);
  EXPECT_DOUBLE_EQ(queue.executor().servo_position(), 17000.0);
  EXPECT_EQ(run("QP"), "0\n\rOK\r\n");
  EXPECT_EQ(run("TP"), "OK\r\n");  // down → up
  frames(1);
  EXPECT_EQ(run("QP"), "1\n\rOK\r\n");
  EXPECT_EQ(run("S2,17500,4"), "OK\r\n");  // below the middle 18500: down
  frames(1);
  EXPECT_FALSE(queue.pen_up());
  EXPECT_EQ(run("S2,17500,5"), "OK\r\n");  // no servo on pin 5: nothing queued
  EXPECT_EQ(queue.waiting(), 0u);
  EXPECT_EQ(run("SP,3"), "OK\r\n");  // up at once, and down becomes up
  frames(1);
  EXPECT_DOUBLE_EQ(queue.executor().servo_position(), 20000.0);
  EXPECT_EQ(pen.down_position(), 20000);
}

TEST_F(EbbCommandsTest, SettingsAndQueriesAnswerAtOnce) {
  EXPECT_EQ(run("V"), std::string(EbbCommands::kDefaultVersion) + "\r\n");
  commands.set_version("EBB 2.5.2");
  EXPECT_EQ(run("V"), "EBB 2.5.2\r\n");
  EXPECT_EQ(run("QU,2"), "QU,64\r\nOK\r\n");
  EXPECT_EQ(run("CU,4,3"), "OK\r\n");
  EXPECT_EQ(run("QU,3"), "QU,3\r\nOK\r\n");
  EXPECT_EQ(run("SL,200,5"), "OK\r\n");
  EXPECT_EQ(run("QL,5"), "200\r\nOK\r\n");
  EXPECT_EQ(commands.variable(5), 200);
  EXPECT_EQ(run("ST,plotter"), "OK\r\n");
  EXPECT_EQ(run("QT"), "plotter\r\nOK\r\n");
  EXPECT_EQ(run("SR,5000"), "OK\r\n");
  EXPECT_EQ(commands.servo_timeout_ms(), 5000u);
  EXPECT_EQ(run("CU,54,1"), "!6 Err: Invalid parameter value\r\n");  // checksums: not here
}

// EM,2 (1/8 for both, motor 2 left as it was: off) then EM,2,1; QE shows 16 >> (mode − 1) = 8.
TEST_F(EbbCommandsTest, EmIsQueuedAndQeShowsWhatTheFrameApplied) {
  EXPECT_EQ(run("EM,2"), "OK\r\n");
  EXPECT_EQ(run("QE"), "0,0\r\nOK\r\n");  // not applied yet: still in the FIFO
  frames(1);
  EXPECT_EQ(run("QE"), "8,0\r\nOK\r\n");
  EXPECT_EQ(run("EM,2,1"), "OK\r\n");
  frames(1);
  EXPECT_EQ(run("QE"), "8,8\r\nOK\r\n");
}

TEST_F(EbbCommandsTest, QmQgAndQsReportWhatTheFramePublished) {
  EXPECT_EQ(run("SM,40,10"), "OK\r\n");    // 10 steps over 1000 ticks: one per 100
  EXPECT_EQ(run("QM"), "QM,1,0,0,1\n\r");  // executing (waiting in the FIFO)
  frames(150);
  EXPECT_EQ(run("QM"), "QM,1,1,0,0\n\r");
  EXPECT_EQ(run("QG"), "1C\r\n");  // pen up 0x10, executing 0x08, motor 1 0x04
  EXPECT_EQ(run("QS"), "1,0\n\rOK\r\n");
  EXPECT_EQ(run("ES"), "1\n\rOK\r\n");  // something was interrupted
  frames(1);
  EXPECT_EQ(run("QM"), "QM,0,0,0,0\n\r");
  EXPECT_EQ(run("CS"), "OK\r\n");
  frames(1);
  EXPECT_EQ(run("QS"), "0,0\n\rOK\r\n");
}

TEST_F(EbbCommandsTest, ResetReturnsToLegacySyntaxDepthOneAndPenUp) {
  EXPECT_EQ(run("CU,4,5"), "OK\r\n");
  EXPECT_EQ(run("CU,10,1"), "\n");
  EXPECT_EQ(run("SP,0"), "SP\n");
  EXPECT_EQ(run("R"), "R\n");  // answered in the syntax R arrived in
  frames(1);
  EXPECT_EQ(run("QU,3"), "QU,1\r\nOK\r\n");
  EXPECT_EQ(run("QP"), "1\n\rOK\r\n");
  EXPECT_TRUE(pen.commanded_up());
}

TEST_F(EbbCommandsTest, PinCommandsReadAndWriteTheEmulatedPorts) {
  EXPECT_EQ(run("PD,B,3,0"), "OK\r\n");  // RB3 an output
  EXPECT_EQ(run("PO,B,3,1"), "OK\r\n");
  EXPECT_EQ(run("PI,B,3"), "PI,1\r\n");
  EXPECT_EQ(run("PI,F,0"), "!6 Err: Invalid parameter value\r\n");  // ports A–E only
}

}  // namespace
}  // namespace stepdance::ebb
