// walk_home after separate walks and after an aborted plot, with the command sequence of the
// AxiDraw software (AxiDraw API 3.9, "inkscape driver/axidraw.py" manual_command and plot_run,
// plotink ebb_motion / ebb_serial): every session starts by asking the EBB, with PI, whether the
// motors are already on at the plot's resolution and sends EM only when they are not, since EM
// clears the step counters walk_home returns by (EBB documentation, HM: "The global step
// counters are reset to zero whenever the motors are enabled, disabled, or have their microstep
// size changed (all via the EM command)").
#include <gtest/gtest.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include <string>

#include "interfaces/ebb_test_host.hpp"
#include "stepdance/core/fault.hpp"

namespace stepdance {
namespace {

/// The AxiDraw software's side, in resolution 2 (1/8 microstepping, the API's default): 40 motor
/// steps per mm on each belt, motor1 = 40·(x + y), motor2 = 40·(x − y).
class AxiDrawApiHost {
 public:
  explicit AxiDrawApiHost(test_support::EbbHost& link) : link_(link) {}

  /// ebb_serial.command(): one line, which must be OK.
  void command(const std::string& text) { EXPECT_EQ(link_.send_and_read_line(text + "\r"), "OK\r\n") << text; }
  /// ebb_serial.query(): one line, and for every query but A, I, MR, PI, QM, QG and V the OK line.
  std::string query(const std::string& text) {
    const std::string reply = link_.send_and_read_line(text + "\r");
    const std::string name = text.substr(0, text.find(','));
    if (name != "PI" && name != "QM" && name != "QG" && name != "V") link_.read_line();
    return reply;
  }
  /// serial_utils.connect() and query_voltage(), then the pen's set-up and lift (servo_init,
  /// pen_raise), then enable_motors() for resolution 2: PI reads, EM,2,2 only when needed.
  void start_session() {
    EXPECT_NE(query("V").find("Firmware Version"), std::string::npos);
    EXPECT_EQ(query("QC"), "0394,0394\r\n");
    command("SC,4,16000");
    command("SC,5,12000");
    command("SC,11,1800");
    command("SC,12,900");
    command("SP,1,250,1");
    if (motors_resolution() != 2) {
      command("EM,2,2");
      ++enables_sent;
    }
  }
  /// walk_mmx / walk_mmy (and plot segments): one SM in motor steps, 100 ms per 10 mm.
  void move_mm(double dx_mm, double dy_mm) {
    const long steps_1 = lround(40.0 * (dx_mm + dy_mm));
    const long steps_2 = lround(40.0 * (dx_mm - dy_mm));
    const long duration_ms = 10 + lround(10.0 * (fabs(dx_mm) + fabs(dy_mm)));
    command("SM," + std::to_string(duration_ms) + "," + std::to_string(steps_1) + "," + std::to_string(steps_2));
  }
  /// The end of every plot_run: "Final timed motion command".
  void end_session() { command("SM,10,0,0"); }
  /// walk_home: exhaust_queue (QG every 50 ms until nothing is queued or moving), QS, and a move back by
  /// −(a + b)/80 mm in x and −(a − b)/80 mm in y, i.e. the counted steps undone.
  void walk_home() {
    for (int i = 0; i < 1000; ++i) {
      const int status = static_cast<int>(strtol(query("QG").c_str(), nullptr, 16));
      if ((status & 15) == 0) break;
      for (int frame = 0; frame < 1250; ++frame) link_.step();  // time.sleep(0.050)
    }
    long a = 0, b = 0;
    ASSERT_EQ(sscanf(query("QS").c_str(), "%ld,%ld", &a, &b), 2);
    move_mm(-(a + b) / 80.0, -(a - b) / 80.0);
  }
  int enables_sent = 0;

 private:
  // plotink ebb_motion.query_enable_motors: the result of both motors at one resolution.
  int motors_resolution() {
    auto high = [this](const char* pin) {
      const std::string reply = query(pin);
      const size_t at = reply.find("PI,");
      return at != std::string::npos && reply.compare(at + 3, 1, "1") == 0;
    };
    const bool enabled = !high("PI,E,0") && !high("PI,C,1");
    const bool ms_1 = high("PI,E,2"), ms_2 = high("PI,E,1"), ms_3 = high("PI,A,6");
    if (!enabled) return 0;
    if (ms_1 && ms_2 && ms_3) return 1;
    if (ms_1 && ms_2) return 2;
    return ms_2 ? 3 : (ms_1 ? 4 : 5);
  }
  test_support::EbbHost& link_;
};

class EbbWalkHomeTest : public test_support::EngineFixture {
 protected:
  void SetUp() override {
    EngineFixture::SetUp();
    ASSERT_EQ(ebb.begin(&link), Status::kOk);
    ASSERT_EQ(dance_start(), Status::kOk);
  }
  void run_until_idle() {
    for (int i = 0; i < 10'000'000 && !ebb.is_idle(); ++i) host.step();
    host.step();
  }

  test_support::FakeByteStream link;
  Eibotboard ebb;
  test_support::EbbHost host{link};
  AxiDrawApiHost api{host};
};

TEST_F(EbbWalkHomeTest, WalkHomeAfterSeparateWalksReturnsToTheStart) {
  api.start_session();  // walk_mmx 20
  api.move_mm(20, 0);
  api.end_session();
  api.start_session();  // walk_mmy 15
  api.move_mm(0, 15);
  api.end_session();
  api.start_session();  // walk_mmx -5
  api.move_mm(-5, 0);
  api.end_session();
  run_until_idle();
  EXPECT_NEAR(ebb.output_x.read_absolute(), 15.0, 1e-9);
  EXPECT_NEAR(ebb.output_y.read_absolute(), 15.0, 1e-9);
  api.start_session();
  api.walk_home();
  api.end_session();
  run_until_idle();
  EXPECT_EQ(api.enables_sent, 1);  // the motors stayed on: only the first session enabled them
  EXPECT_NEAR(ebb.output_x.read_absolute(), 0.0, 1e-9);
  EXPECT_NEAR(ebb.output_y.read_absolute(), 0.0, 1e-9);
  EXPECT_EQ(api.query("QS"), "0,0\n");
}

TEST_F(EbbWalkHomeTest, WalkHomeAfterAnAbortedPlotReturnsToTheStart) {
  api.start_session();
  api.command("CU,4,8");  // a deeper FIFO than the EBB's default, as a fast client streams
  const double square[][2] = {{30, 20}, {40, 0}, {0, 40}};  // the rest is never sent
  for (int i = 0; i < 3; ++i) {                             // the travel, then the pen down and two sides of the square
    if (i == 1) api.command("SP,0,150,1");
    api.move_mm(square[i][0], square[i][1]);
  }
  // The pause: the API stops feeding, lifts the pen and ends the session; nothing is lost.
  api.command("SP,1,250,1");
  api.end_session();
  run_until_idle();
  EXPECT_NEAR(ebb.output_x.read_absolute(), 70.0, 1e-9);
  EXPECT_NEAR(ebb.output_y.read_absolute(), 60.0, 1e-9);
  api.start_session();
  api.walk_home();
  api.end_session();
  run_until_idle();
  EXPECT_EQ(api.enables_sent, 1);
  EXPECT_NEAR(ebb.output_x.read_absolute(), 0.0, 1e-9);
  EXPECT_NEAR(ebb.output_y.read_absolute(), 0.0, 1e-9);
}

TEST_F(EbbWalkHomeTest, WalkHomeAfterAnEmergencyStopReturnsToWhereTheMotorsStopped) {
  // ES,1 stops and disables the drivers without touching the counters (it is not EM), so the
  // next session enables them again (clearing the counters, as EM does) and home is then where
  // the carriage stopped: what the real board does.
  api.start_session();
  api.move_mm(40, 0);
  for (int i = 0; i < 5000; ++i) host.step();  // 200 ms of the 410 ms move
  EXPECT_EQ(api.query("ES,1").substr(0, 1), "1");
  const std::string counted = api.query("QS");
  EXPECT_NE(counted, "0,0\n");  // kept by ES
  const double stopped_x = ebb.output_x.read_absolute();
  api.start_session();
  EXPECT_EQ(api.enables_sent, 2);
  api.walk_home();
  run_until_idle();
  EXPECT_NEAR(ebb.output_x.read_absolute(), stopped_x, 1e-9);
}

TEST_F(EbbWalkHomeTest, EnableAndClearZeroTheCountersAndBothAccumulators) {
  // CS "zeros out … the global step position[s] … It also zeros out both step accumulators";
  // every EM does the same on the real firmware. After a move that leaves the accumulators half
  // full, an LM from zeroed accumulators takes its first step after exactly ⌈2^31 / Rate⌉ ticks.
  for (const char* clear : {"CS", "EM,1,1"}) {
    SCOPED_TRACE(clear);
    ASSERT_EQ(host.exchange("LM,1610612736,1,0,1610612736,1,0\r"), "OK\r\n");  // three quarters of a step per tick
    run_until_idle();  // one step in two ticks: 2^30 left in each accumulator
    ASSERT_EQ(host.exchange(std::string(clear) + "\r"), "OK\r\n");
    run_until_idle();
    EXPECT_EQ(host.exchange("QS\r"), "0,0\n\rOK\r\n");
    ASSERT_EQ(host.exchange("LM,536870912,1,0,536870912,1,0\r"), "OK\r\n");  // a quarter step per tick
    const double start = ebb.output_x.read_absolute();
    int ticks = 0;
    while (ebb.output_x.read_absolute() == start && ticks < 100) {
      hal_manual::run_frames(1);
      ++ticks;
    }
    EXPECT_EQ(ticks, 4);  // from a half-full accumulator it would have been 2
    run_until_idle();
  }
}

}  // namespace
}  // namespace stepdance
