// The EBB emulation as plotter software sees it: byte-exact replies in both syntaxes, the LM/LT
// accumulator algorithm tick for tick against an independent model, exact SM/XM/HM endpoints,
// flow control, pen and errors that change nothing.
#include "stepdance/interfaces/ebb/eibotboard.hpp"

#include <gtest/gtest.h>

#include <math.h>

#include <map>
#include <string>
#include <vector>

#include "hal_manual.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/core/fault.hpp"
#include "support/engine_fixture.hpp"
#include "support/fake_byte_stream.hpp"

namespace stepdance {
namespace {

/// The LM/LT algorithm as the EBB documentation states it, written independently: per axis,
/// Rate starts at Rate − Accel/2; every tick Rate += Accel (a negative Rate rolls over by 2^31),
/// Accumulator += Rate, and a step is taken (2^31 subtracted) when it reaches 2^31.
struct ReferenceAxis {
  int64_t rate, accel, accumulator = 0;
  int64_t steps_left;  // −1: time-limited
  int64_t taken = 0;
  ReferenceAxis(int64_t rate_in, int64_t accel_in, int64_t steps)
      : rate(rate_in - accel_in / 2), accel(accel_in), steps_left(steps) {}
  void tick() {
    if (steps_left == 0) return;
    rate += accel;
    if (rate < 0) rate += (int64_t{1} << 31);
    accumulator += rate;
    if (accumulator >= (int64_t{1} << 31)) {
      accumulator -= (int64_t{1} << 31);
      ++taken;
      if (steps_left > 0) --steps_left;
    }
  }
};

class EibotboardTest : public test_support::EngineFixture {
 protected:
  void SetUp() override {
    EngineFixture::SetUp();
    ebb.set_kinematics(EBB_KINEMATICS_XY);  // motor positions straight out on x and y
    ASSERT_EQ(ebb.begin(&host), Status::kOk);
    ASSERT_EQ(dance_start(), Status::kOk);
  }
  /// One loop pass then one frame (a 40 µs tick).
  void step() {
    dance_loop();
    hal_manual::run_frames(1);
  }
  /// Sends a command and returns the reply, running frames while it waits (a motion command
  /// that finds the FIFO full is answered only when the FIFO has room, as a client sees it).
  std::string exchange(const std::string& text) {
    host.take();
    host.send(text);
    dance_loop();
    for (int i = 0; i < 1'000'000 && host.from_board.empty(); ++i) step();
    return host.take();
  }
  /// Motor positions in (1/16) steps from the outputs (XY kinematics, 80 per mm).
  int64_t motor(int axis) const {
    const double mm = axis == 0 ? ebb.output_x.read_absolute() : ebb.output_y.read_absolute();
    return llround(mm * 80.0);
  }
  void run_until_idle(int limit = 10'000'000) {
    for (int i = 0; i < limit; ++i) {
      step();
      ++polls_;
      if (exchange("QM\r") == "QM,0,0,0,0\n\r") return;
    }
    FAIL() << "never idle";
  }

  test_support::FakeByteStream host;
  Eibotboard ebb;
  uint64_t polls_ = 0;  // QM queries run_until_idle() sent
};

TEST_F(EibotboardTest, VersionInEitherCaseAndLineEndingsThatDoNotCorruptTheNext) {
  const std::string version = std::string(Eibotboard::kDefaultVersion) + "\r\n";
  EXPECT_EQ(exchange("V\r"), version);
  EXPECT_EQ(exchange("v\r"), version);
  EXPECT_EQ(exchange("V\r\nV\r"), version + version);  // CR LF is one line end
  EXPECT_EQ(exchange("V\nV\n"), version + version);    // so is a lone LF
  EXPECT_EQ(exchange("\xff\x01V\r"), version);         // binary garbage is dropped
}

TEST_F(EibotboardTest, LegacyAndFutureSyntaxRepliesAreByteExact) {
  EXPECT_EQ(exchange("QM\r"), "QM,0,0,0,0\n\r");
  EXPECT_EQ(exchange("QS\r"), "0,0\n\rOK\r\n");
  EXPECT_EQ(exchange("QP\r"), "1\n\rOK\r\n");
  EXPECT_EQ(exchange("QB\r"), "0\r\nOK\r\n");
  EXPECT_EQ(exchange("QG\r"), "10\r\n");  // pen up, nothing else
  EXPECT_EQ(exchange("QE\r"), "0,0\r\nOK\r\n");
  EXPECT_EQ(exchange("SL,242,21\r"), "OK\r\n");
  EXPECT_EQ(exchange("QL,21\r"), "242\r\nOK\r\n");
  EXPECT_EQ(exchange("ST,East EBB\r"), "OK\r\n");
  EXPECT_EQ(exchange("QT\r"), "East EBB\r\nOK\r\n");
  EXPECT_EQ(exchange("QU,2\r"), "QU,64\r\nOK\r\n");
  EXPECT_EQ(exchange("ES\r"), "0\n\rOK\r\n");
  EXPECT_EQ(exchange("CU,10,1\r"), "\n");  // the switch's own odd reply
  EXPECT_EQ(exchange("QM\r"), "QM,0,0,0,0\n");
  EXPECT_EQ(exchange("QS\r"), "QS,0,0\n");
  EXPECT_EQ(exchange("QG\r"), "QG,10\n");
  EXPECT_EQ(exchange("V\r"), std::string("V,") + Eibotboard::kDefaultVersion + "\n");
  EXPECT_EQ(exchange("SM,10,0,0\r"), "SM\n");
  EXPECT_EQ(exchange("QU,3\r"), "QU,1\n");
  EXPECT_EQ(exchange("SM,100\r"), "SM,!4 Err: Missing parameter(s)\n");
  EXPECT_EQ(exchange("CU,10,0\r"), "CUOK\r\n");
  EXPECT_EQ(exchange("QM\r").substr(0, 3), "QM,");
}

/// One command and its two replies, as the EBB command documentation (firmware v3, "EBB Command
/// Set") gives them: "Response (legacy mode; default)" and "Response (future mode)".
struct DocumentedReply {
  const char* command;
  const char* legacy;
  const char* future;
};

// Every command the emulation implements, in an order whose state each reply follows from: power-on
// (motors off, pen up, counters zero), then settings, then motion queued into an 8-deep FIFO, the
// stop that interrupts it, and the reset.
const DocumentedReply kEveryCommand[] = {
    {"QM", "QM,0,0,0,0\n\r", "QM,0,0,0,0\n"},
    {"QG", "10\r\n", "QG,10\n"},  // pen up (bit 4), nothing else
    {"QS", "0,0\n\rOK\r\n", "QS,0,0\n"},
    {"CS", "OK\r\n", "CS\n"},
    {"QP", "1\n\rOK\r\n", "QP,1\n"},
    {"QB", "0\r\nOK\r\n", "QB,0\n"},
    {"QC", "0394,0394\r\nOK\r\n", "QC,0394,0394\n"},
    {"QE", "0,0\r\nOK\r\n", "QE,0,0\n"},
    {"QR", "1\n\rOK\r\n", "QR,1\n"},
    {"SL,7,3", "OK\r\n", "SL\n"},
    {"QL,3", "7\r\nOK\r\n", "QL,7\n"},
    {"ST,Plotter 2", "OK\r\n", "ST\n"},
    {"QT", "Plotter 2\r\nOK\r\n", "QT,Plotter 2\n"},
    {"SC,4,20000", "OK\r\n", "SC\n"},
    {"SC,5,16000", "OK\r\n", "SC\n"},
    {"SC,10,65535", "OK\r\n", "SC\n"},
    {"SR,60000,1", "OK\r\n", "SR\n"},
    {"CU,4,8", "OK\r\n", "CU\n"},
    {"QU,2", "QU,64\r\nOK\r\n", "QU,64\n"},
    {"QU,3", "QU,8\r\nOK\r\n", "QU,8\n"},
    {"EM,1,1", "OK\r\n", "EM\n"},
    {"SM,10,5,5", "OK\r\n", "SM\n"},
    {"XM,10,5,0", "OK\r\n", "XM\n"},
    {"LM,85899346,5,0,0,0,0", "OK\r\n", "LM\n"},
    {"LT,100,85899346,0,0,0", "OK\r\n", "LT\n"},
    {"HM,1000", "OK\r\n", "HM\n"},
    {"SP,0,10", "OK\r\n", "SP\n"},
    {"QP", "1\n\rOK\r\n", "QP,1\n"},  // "reports the new state only after the pen move has started"
    {"TP", "OK\r\n", "TP\n"},
    // The ninth motion command finds the 8-deep FIFO full: its OK comes once the frame has taken
    // EM (no time) and started SM, so the FIFO then holds XM, LM, LT, HM, SP, TP and S2.
    {"S2,20000,4", "OK\r\n", "S2\n"},
    {"QU,6", "QU,07\r\nOK\r\n", "QU,07\n"},
    {"QM", "QM,1,1,1,1\n\r", "QM,1,1,1,1\n"},
    {"QG", "1F\r\n", "QG,1F\n"},  // pen up (SP not started), executing, both motors, FIFO
    {"QE", "16,16\r\nOK\r\n", "QE,16,16\n"},
    {"ES", "1\n\rOK\r\n", "ES,1\n"},
    {"R", "OK\r\n", "R\n"},
};

TEST_F(EibotboardTest, EveryCommandRepliesAsDocumentedInEitherSyntax) {
  for (const bool future : {false, true}) {
    SCOPED_TRACE(future ? "future syntax" : "legacy syntax");
    if (future) {
      ASSERT_EQ(exchange("R\r"), "OK\r\n");  // back to power-on
      for (int i = 0; i < 10; ++i) step();
      ASSERT_EQ(exchange("CU,10,1\r"), "\n");
    }
    for (const DocumentedReply& row : kEveryCommand) {
      EXPECT_EQ(exchange(std::string(row.command) + "\r"), future ? row.future : row.legacy) << row.command;
    }
  }
}

TEST_F(EibotboardTest, AcknowledgementsOffDropOnlyTheOkAndOnlyInLegacySyntax) {
  // CU,1,0: "disables the OK response"; the line endings stay. No effect in future syntax.
  EXPECT_EQ(exchange("CU,1,0\r"), "\r\n");
  EXPECT_EQ(exchange("SC,4,20000\r"), "\r\n");
  EXPECT_EQ(exchange("QS\r"), "0,0\n\r\r\n");
  EXPECT_EQ(exchange("QU,3\r"), "QU,1\r\n\r\n");
  EXPECT_EQ(exchange("QM\r"), "QM,0,0,0,0\n\r");  // never had an OK
  EXPECT_EQ(exchange("CU,10,1\r"), "\n");
  EXPECT_EQ(exchange("SC,4,20000\r"), "SC\n");
  EXPECT_EQ(exchange("CU,10,0\r"), "CU\r\n");  // half made before the switch: "CU", then no OK
  EXPECT_EQ(exchange("CU,1,1\r"), "OK\r\n");
}

TEST_F(EibotboardTest, ErrorsGetTheDocumentedReplyAndChangeNothing) {
  EXPECT_EQ(exchange("SM,100\r"), "!4 Err: Missing parameter(s)\r\n");
  EXPECT_EQ(exchange("SM,100A\r"), "!5 Err: Need comma next, found: 'A'\r\n");
  EXPECT_EQ(exchange("TP,-1\r"), "!6 Err: Invalid parameter value\r\n");
  EXPECT_EQ(exchange("SM,1,1,1,0,0\r"), "!7 Err: Extra parameter\r\n");
  EXPECT_EQ(exchange("BB\r"), "!8 Err: Unknown command 'BB:4242'\r\n");
  EXPECT_EQ(exchange("B\r"), "!8 Err: Unknown command 'B:42'\r\n");
  EXPECT_EQ(exchange("SM,0,10,10\r"), "!6 Err: Invalid parameter value\r\n");
  EXPECT_EQ(exchange("EM,6\r"), "!6 Err: Invalid parameter value\r\n");
  EXPECT_EQ(exchange("XM,1,100,0\r"), "!0 Err: <axis1> step rate too high\r\n");
  EXPECT_EQ(exchange(std::string(300, 'S') + "\r"), "!3 Err: RX Buffer overrun\r\n");
  EXPECT_EQ(exchange("V\r"), std::string(Eibotboard::kDefaultVersion) + "\r\n");  // and then all is well
  for (int i = 0; i < 100; ++i) step();
  EXPECT_EQ(exchange("QS\r"), "0,0\n\rOK\r\n");
  EXPECT_EQ(exchange("QM\r"), "QM,0,0,0,0\n\r");
  EXPECT_EQ(ebb.errors_replied(), 10u);
}

TEST_F(EibotboardTest, LowLevelMoveMatchesTheAccumulatorAlgorithmTickForTick) {
  // Documentation examples 6 (accelerating, 50 steps in about 77 ms) and 7 (two axes).
  const struct {
    int64_t rate1, steps1, accel1, rate2, steps2, accel2;
  } moves[] = {
      {42950000, 50, 13400, 0, 0, 0}, {17179000, 75, -687, 8592000, 75, 687}, {85899346, 10, 0, 17180814, 2, 0}};
  int64_t accumulators[2] = {0, 0};  // carried from move to move, as the EBB does without Clear
  for (const auto& m : moves) {
    const int64_t start1 = motor(0), start2 = motor(1);
    ReferenceAxis axis1(m.rate1, m.accel1, m.steps1), axis2(m.rate2, m.accel2, m.steps2);
    axis1.accumulator = accumulators[0];
    axis2.accumulator = accumulators[1];
    char command[128];
    snprintf(command, sizeof command, "LM,%lld,%lld,%lld,%lld,%lld,%lld\r", (long long)m.rate1, (long long)m.steps1,
             (long long)m.accel1, (long long)m.rate2, (long long)m.steps2, (long long)m.accel2);
    ASSERT_EQ(exchange(command), "OK\r\n");
    int ticks = 0;
    while (axis1.steps_left > 0 || axis2.steps_left > 0) {
      hal_manual::run_frames(1);  // the frame takes the move from the FIFO and runs one tick
      axis1.tick();
      axis2.tick();
      ++ticks;
      ASSERT_EQ(motor(0) - start1, axis1.taken) << command << " tick " << ticks;
      ASSERT_EQ(motor(1) - start2, axis2.taken) << command << " tick " << ticks;
      ASSERT_LT(ticks, 1'000'000);
    }
    accumulators[0] = axis1.accumulator;
    accumulators[1] = axis2.accumulator;
    hal_manual::run_frames(1);
    EXPECT_EQ(exchange("QM\r"), "QM,0,0,0,0\n\r") << command;
    if (m.steps1 == 50) {
      EXPECT_NEAR(ticks * 40e-6, 0.077, 0.001);  // "The move will take 77 ms"
    }
    if (m.steps1 == 10) {
      EXPECT_EQ(ticks, 250);  // "a 10 ms long move"
    }
  }
}

TEST_F(EibotboardTest, TimeLimitedMoveCoversTheDocumentedSteps) {
  // LT example 3: "The move will cover 75 steps on each axis" in 12,500 intervals.
  ReferenceAxis axis1(17179000, -687, -1), axis2(8592000, 687, -1);
  ASSERT_EQ(exchange("LT,12500,17179000,-687,8592000,687\r"), "OK\r\n");
  for (int tick = 1; tick <= 12500; ++tick) {
    hal_manual::run_frames(1);
    axis1.tick();
    axis2.tick();
    ASSERT_EQ(motor(0), axis1.taken) << "tick " << tick;
    ASSERT_EQ(motor(1), axis2.taken) << "tick " << tick;
  }
  EXPECT_NEAR(axis1.taken, 75, 1);
  EXPECT_NEAR(axis2.taken, 75, 1);
  hal_manual::run_frames(1);
  EXPECT_EQ(exchange("QM\r"), "QM,0,0,0,0\n\r");
}

TEST_F(EibotboardTest, StepperMovesEndExactlyAndHomeReturns) {
  ASSERT_EQ(exchange("SM,1000,250,-766\r"), "OK\r\n");
  run_until_idle();
  EXPECT_EQ(exchange("QS\r"), "250,-766\n\rOK\r\n");
  EXPECT_EQ(motor(0), 250);
  EXPECT_EQ(motor(1), -766);
  ASSERT_EQ(exchange("XM,1000,550,-1234\r"), "OK\r\n");  // motor1 = A + B, motor2 = A − B
  run_until_idle();
  EXPECT_EQ(exchange("QS\r"), "-434,1018\n\rOK\r\n");  // 250 + 550 − 1234, −766 + 550 + 1234
  ASSERT_EQ(exchange("HM,5000,100,-50\r"), "OK\r\n");
  run_until_idle();
  EXPECT_EQ(exchange("QS\r"), "100,-50\n\rOK\r\n");
  ASSERT_EQ(exchange("HM,5000\r"), "OK\r\n");
  run_until_idle();
  EXPECT_EQ(exchange("QS\r"), "0,0\n\rOK\r\n");
  EXPECT_EQ(motor(0), 0);
  EXPECT_EQ(motor(1), 0);
  ASSERT_EQ(exchange("CS\r"), "OK\r\n");
}

// The emulation keeps the EBB's 40 µs tick at any frame period: a 1000 ms move takes 1000 ms of
// 10 µs frames (100 000 of them), not a quarter of that.
TEST_F(EibotboardTest, MovesKeepTheEbbTimeBaseInTenMicrosecondFrames) {
  engine().stop();
  ASSERT_EQ(set_frame_period_us(10), Status::kOk);
  ASSERT_EQ(dance_start(), Status::kOk);
  ASSERT_EQ(exchange("SM,1000,250,-766\r"), "OK\r\n");
  const uint32_t started = engine().frame_count();
  for (int i = 0; i < 200000 && (motor(0) != 250 || motor(1) != -766); ++i) step();
  const uint32_t frames = engine().frame_count() - started;
  EXPECT_EQ(motor(0), 250);
  EXPECT_EQ(motor(1), -766);
  EXPECT_GE(frames, 99000u);  // 1000 ms: 25 000 EBB ticks of 4 frames
  EXPECT_LE(frames, 100000u);
}

TEST_F(EibotboardTest, MicrostepModeScalesMotionAndEnableClearsTheCounters) {
  ASSERT_EQ(exchange("EM,2,2\r"), "OK\r\n");  // 1/8: one step is two 1/16 steps
  ASSERT_EQ(exchange("SM,100,40,-20\r"), "OK\r\n");
  run_until_idle();
  EXPECT_EQ(exchange("QE\r"), "8,8\r\nOK\r\n");
  EXPECT_EQ(exchange("QS\r"), "40,-20\n\rOK\r\n");
  EXPECT_EQ(motor(0), 80);
  EXPECT_EQ(motor(1), -40);
  ASSERT_EQ(exchange("EM,1,1\r"), "OK\r\n");  // counters restart, the motors stay put
  run_until_idle();
  EXPECT_EQ(exchange("QS\r"), "0,0\n\rOK\r\n");
  EXPECT_EQ(motor(0), 80);
}

TEST_F(EibotboardTest, FullFifoHoldsTheCommandAndNothingIsLost) {
  // Depth 1: the first move runs, the second waits in the FIFO, the third waits unread.
  std::string replies;
  host.send("SM,40,10,0\rSM,40,10,0\rSM,40,10,0\rSM,40,10,0\rSM,40,10,0\rQS\r");
  for (int i = 0; i < 20000; ++i) {
    step();
    replies += host.take();
  }
  // Each OK came only when its move fit; QS answered at once after the last one was queued.
  EXPECT_EQ(replies.substr(0, 20), "OK\r\nOK\r\nOK\r\nOK\r\nOK\r\n");
  run_until_idle();
  EXPECT_EQ(exchange("QS\r"), "50,0\n\rOK\r\n");
  EXPECT_EQ(motor(0), 50);
  // Depth 1 keeps three in play (one running, one in the FIFO, one unread), so SM 2 to 5 each
  // waited once; every line was answered and every move taken. QM and QS polls count as commands.
  struct Counters final : CounterSink {
    std::map<std::string, uint64_t> values;
    void counter(const char* name, uint64_t value) override { values[name] = value; }
  } counters;
  ebb.report_counters(counters);
  EXPECT_EQ(counters.values["fifo_full_waits"], 4u);
  EXPECT_EQ(counters.values["moves_started"], 5u);
  EXPECT_EQ(counters.values["replies_dropped"], 0u);
  EXPECT_EQ(counters.values["commands"], 6u + polls_ + 1);  // + run_until_idle's QMs + the last QS
}

TEST_F(EibotboardTest, QueryMotorsFollowsExecutionAndEmergencyStopFlushes) {
  ASSERT_EQ(exchange("SM,1000,1000,0\r"), "OK\r\n");
  ASSERT_EQ(exchange("SM,1000,1000,0\r"), "OK\r\n");
  for (int i = 0; i < 100; ++i) step();
  EXPECT_EQ(exchange("QM\r"), "QM,1,1,0,1\n\r");
  EXPECT_EQ(exchange("QG\r"), "1D\r\n");  // pen up, executing, motor 1, FIFO
  EXPECT_EQ(exchange("ES\r"), "1\n\rOK\r\n");
  step();
  EXPECT_EQ(exchange("QM\r"), "QM,0,0,0,0\n\r");
  const int64_t stopped = motor(0);
  EXPECT_GT(stopped, 0);
  EXPECT_LT(stopped, 1000);
  for (int i = 0; i < 1000; ++i) step();
  EXPECT_EQ(motor(0), stopped);
}

TEST_F(EibotboardTest, AnAlarmStopsTheMotorsRefusesMotorMovesAndStillLiftsThePen) {
  ASSERT_EQ(exchange("CU,4,8\r"), "OK\r\n");  // FIFO depth 8: one move running, one waiting
  ASSERT_EQ(exchange("SP,0\r"), "OK\r\n");    // pen down
  ASSERT_EQ(exchange("SM,1000,1000,0\r"), "OK\r\n");
  ASSERT_EQ(exchange("SM,1000,1000,0\r"), "OK\r\n");
  for (int i = 0; i < 200; ++i) step();
  const int64_t before = motor(0);
  ASSERT_GT(before, 0);
  report_fault(FaultLevel::kAlarm, FaultReason::kLimitHit, "test", "limit switch");
  step();
  const int64_t stopped = motor(0);
  EXPECT_LE(stopped - before, 1);                 // at most the step of the frame that saw the alarm
  EXPECT_EQ(exchange("QM\r"), "QM,0,0,0,0\n\r");  // the running and the waiting move are gone
  for (int i = 0; i < 1000; ++i) step();
  EXPECT_EQ(motor(0), stopped);
  EXPECT_EQ(exchange("SM,100,50,0\r"), "!9 Err: Alarm raised: motor moves refused until it is cleared\r\n");
  EXPECT_EQ(exchange("LM,85899346,100,0,0,0,0\r"), "!9 Err: Alarm raised: motor moves refused until it is cleared\r\n");
  ASSERT_EQ(exchange("SP,1\r"), "OK\r\n");  // the pen still lifts
  run_until_idle();
  EXPECT_EQ(exchange("QP\r"), "1\n\rOK\r\n");
  EXPECT_EQ(motor(0), stopped);
  struct Counters final : CounterSink {
    std::map<std::string, uint64_t> values;
    void counter(const char* name, uint64_t value) override { values[name] = value; }
  } counters;
  ebb.report_counters(counters);
  EXPECT_EQ(counters.values["alarm_stops"], 2u);  // the running move and the waiting one
  clear_alarm();
  ASSERT_EQ(exchange("SM,100,50,0\r"), "OK\r\n");  // cleared: motion again, from where it stopped
  run_until_idle();
  EXPECT_EQ(motor(0), stopped + 50);
}

TEST_F(EibotboardTest, PenMovesTheServoOutputWithRateAndDelay) {
  ebb.set_ratio_z(1, 1);  // z in servo-board steps (µs from 1.5 ms)
  step();
  EXPECT_NEAR(ebb.output_z.read_absolute(), 20000 / 12.0 - 1500, 1e-9);  // pen up at power-on
  ASSERT_EQ(exchange("SC,5,12000\r"), "OK\r\n");                         // down at 1.0 ms
  ASSERT_EQ(exchange("SC,12,400\r"), "OK\r\n");                          // 400/12 µs per 24 ms
  ASSERT_EQ(exchange("SP,0,300\r"), "OK\r\n");
  EXPECT_EQ(exchange("QP\r"), "1\n\rOK\r\n");  // still in the FIFO
  step();
  EXPECT_EQ(exchange("QP\r"), "0\n\rOK\r\n");    // started
  ASSERT_EQ(exchange("SM,10,5,0\r"), "OK\r\n");  // waits for the pen's 300 ms delay
  // 8000 units at 400 per 24 ms: 20 periods = 480 ms to reach the down position.
  for (int i = 0; i < 6000; ++i) step();  // 240 ms
  EXPECT_NEAR(ebb.output_z.read_absolute(), (20000 - 4000) / 12.0 - 1500, 0.5);
  EXPECT_EQ(motor(0), 0);                 // the delay holds the move back
  for (int i = 0; i < 6500; ++i) step();  // 500 ms in all
  EXPECT_NEAR(ebb.output_z.read_absolute(), 12000 / 12.0 - 1500, 1e-9);
  EXPECT_EQ(motor(0), 5);
  ASSERT_EQ(exchange("S2,24000,4,0,0\r"), "OK\r\n");  // saxi's pen command on RB1
  step();
  step();
  EXPECT_NEAR(ebb.output_z.read_absolute(), 24000 / 12.0 - 1500, 1e-9);
  EXPECT_EQ(exchange("QP\r"), "1\n\rOK\r\n");
}

TEST_F(EibotboardTest, IdleOnlyWhenNothingRunsWaitsOrSlews) {
  step();
  EXPECT_TRUE(ebb.is_idle());
  ASSERT_EQ(exchange("SC,12,400\r"), "OK\r\n");  // down at 400/12 µs per 24 ms
  ASSERT_EQ(exchange("SP,0\r"), "OK\r\n");
  EXPECT_FALSE(ebb.is_idle());  // in the FIFO
  // From the default up (20000) to down (16000): 4000 / 400 = 10 periods of 24 ms = 6000 ticks.
  for (int i = 0; i < 5990; ++i) step();
  EXPECT_FALSE(ebb.is_idle());  // the servo still slews
  for (int i = 0; i < 20; ++i) step();
  EXPECT_TRUE(ebb.is_idle());
  ASSERT_EQ(exchange("SM,2,10,0\r"), "OK\r\n");
  step();
  EXPECT_FALSE(ebb.is_idle());  // moving
  for (int i = 0; i < 60; ++i) step();
  EXPECT_TRUE(ebb.is_idle());  // 2 ms = 50 ticks
}

TEST_F(EibotboardTest, OversizedServoTimeoutAndClientSetupAreAccepted) {
  // saxi's start and end of a plot.
  EXPECT_EQ(exchange("EM,2,2\r"), "OK\r\n");
  EXPECT_EQ(exchange("SR,0,1\r"), "OK\r\n");
  EXPECT_EQ(exchange("QC\r"), "0394,0394\r\nOK\r\n");
  EXPECT_EQ(exchange("SR,60000000,0\r"), "OK\r\n");
  EXPECT_EQ(exchange("EM,0,0\r"), "OK\r\n");
  EXPECT_EQ(exchange("R\r"), "OK\r\n");
}

}  // namespace
}  // namespace stepdance
