// The step-rate ceiling: a channel emits at most one step per frame (25,000 steps/s at 40 µs),
// so an EBB move whose motors would outrun it is slowed down as a whole — every motor keeps its
// place on the move's path — and the board counts and reports it. Expected values are closed-form
// geometry and the frame rate, not the emulation's own figures.
#include <gtest/gtest.h>

#include <math.h>

#include <map>
#include <string>

#include "interfaces/ebb_test_host.hpp"
#include "stepdance/core/counters.hpp"
#include "stepdance/core/fault.hpp"
#include "stepdance/core/frame_period.hpp"
#include "stepdance/motion/channel.hpp"
#include "stepdance/motion/kinematics_core_xy.hpp"

namespace stepdance {
namespace {

constexpr double kStepsPerMm16 = 2032.0 / 25.4;  // the AxiDraw's 1/16 microsteps per mm
constexpr double kTwoTo31 = 2147483648.0;

struct Counters final : CounterSink {
  std::map<std::string, uint64_t> values;
  void counter(const char* name, uint64_t value) override { values[name] = value; }
};

/// Eibotboard → CoreXY → two channels at 80 steps/mm (the AxiDraw's belts, 1/16 microsteps).
class EbbRateTest : public test_support::EngineFixture {
 protected:
  void start(uint32_t frame_period_us) {
    ASSERT_EQ(set_frame_period_us(frame_period_us), Status::kOk);
    ASSERT_EQ(channel_a.begin(), Status::kOk);
    ASSERT_EQ(channel_b.begin(), Status::kOk);
    channel_a.set_ratio(25.4, 2032);
    channel_b.set_ratio(25.4, 2032);
    ASSERT_EQ(kinematics.begin(), Status::kOk);
    kinematics.output_a.map(&channel_a.input_target_position);
    kinematics.output_b.map(&channel_b.input_target_position);
    ASSERT_EQ(ebb.begin(&link), Status::kOk);
    ebb.output_x.map(&kinematics.input_x);
    ebb.output_y.map(&kinematics.input_y);
    ASSERT_EQ(dance_start(), Status::kOk);
    ASSERT_EQ(host.exchange("EM,2,2\r"), "OK\r\n");  // 1/8: one EBB step is two 1/16 steps
    for (int i = 0; i < 10; ++i) host.step();
  }
  uint64_t counter(const char* name) {
    Counters counters;
    ebb.report_counters(counters);
    return counters.values[name];
  }

  test_support::FakeByteStream link;
  Eibotboard ebb;
  KinematicsCoreXY kinematics;
  Channel channel_a;
  Channel channel_b;
  test_support::EbbHost host{link};
};

// 50 mm at 400 mm/s along (3, 4)/5: x 30 mm, y 40 mm. In motor terms (1/8, 40 steps/mm)
// motor 1 = x + y: 2800 steps at 22,400 steps/s, motor 2 = x − y: −400 steps at 3,200 steps/s,
// both in 0.125 s. LM's Rate is 2^31 · steps/s / 25,000.
const std::string kFastLine = "LM," + std::to_string(llround(kTwoTo31 * 22400 / 25000)) + ",2800,0," +
                              std::to_string(llround(kTwoTo31 * 3200 / 25000)) + ",-400,0,3\r";

TEST_F(EbbRateTest, AFastMoveIsSlowedToTheStepRateAndDrawsItsPathExactly) {
  start(40);
  ASSERT_EQ(host.exchange(kFastLine), "OK\r\n");
  // The plan in 1/16 steps: channel a from 0 to 5600, channel b from 0 to −800, on one line.
  const double end_a = 70.0 * kStepsPerMm16, end_b = -10.0 * kStepsPerMm16;
  const double length = hypot(end_a, end_b);
  double worst_off_line = 0.0;
  int frames = 0;
  bool queried = false;
  while ((channel_a.current_position != end_a || channel_b.current_position != end_b) && frames < 100000) {
    host.step();
    ++frames;
    const double a = channel_a.current_position, b = channel_b.current_position;
    const double off_line = fabs(a * end_b - b * end_a) / length;  // distance from the plan's line
    if (off_line > worst_off_line) worst_off_line = off_line;
    ASSERT_LE(a, end_a);
    ASSERT_GE(b, end_b);
    if (!queried && frames == 2000) {  // QM during the move, as before: executing, both moving
      EXPECT_EQ(host.exchange("QM\r"), "QM,1,1,1,0\n\r");
      queried = true;
    }
  }
  // Within one EBB step (two 1/16 steps) of the plan at every frame.
  EXPECT_LE(worst_off_line, 2.0);
  // As long as the rate allows: 5600 steps of channel a at one per 40 µs frame = 5600 frames
  // (the move itself asked for 0.125 s = 3125 frames).
  EXPECT_NEAR(frames, 5600, 3);
  EXPECT_EQ(counter("moves_stretched"), 1u);
  EXPECT_EQ(warning_count(), 1u);
  FaultReport report;
  ASSERT_TRUE(recent_fault_report(0, report));
  EXPECT_EQ(report.level, FaultLevel::kWarning);
  EXPECT_STREQ(report.source, "Eibotboard");
  // The move and its rates: LM's 22,400 steps/s at 1/8 are 44,800 1/16 steps/s; one 1/16 step
  // per 40 µs frame carries 25,000.
  const std::string detail = report.detail;
  EXPECT_NE(detail.find("LM"), std::string::npos) << detail;
  EXPECT_NE(detail.find("44800"), std::string::npos) << detail;
  EXPECT_NE(detail.find("25000"), std::string::npos) << detail;
  WarningTally tally;
  ASSERT_TRUE(warning_tally(0, tally));
  EXPECT_STREQ(tally.source, "Eibotboard");
  EXPECT_EQ(tally.reason, FaultReason::kOverrun);
  EXPECT_EQ(tally.count, 1u);
  EXPECT_FALSE(warning_tally(1, tally));
  for (int i = 0; i < 10; ++i) host.step();
  EXPECT_EQ(host.exchange("QM\r"), "QM,0,0,0,0\n\r");
  EXPECT_EQ(host.exchange("QS\r"), "2800,-400\n\rOK\r\n");
}

TEST_F(EbbRateTest, RepeatedStretchesAreNamedOnceAndCountedEach) {
  start(40);
  ASSERT_EQ(host.exchange("CU,4,16\r"), "OK\r\n");
  for (int i = 0; i < 6; ++i) {  // six fast moves back and forth, 5600 frames (0.224 s) each
    const bool back = i % 2 == 1;
    std::string line = kFastLine;
    if (back)
      line = "LM," + std::to_string(llround(kTwoTo31 * 22400 / 25000)) + ",-2800,0," +
             std::to_string(llround(kTwoTo31 * 3200 / 25000)) + ",400,0,3\r";
    ASSERT_EQ(host.exchange(line), "OK\r\n");
  }
  for (int i = 0; i < 40000; ++i) host.step();
  EXPECT_EQ(counter("moves_stretched"), 6u);
  // The first stretch is reported with its move and rates; the other five are counted only.
  EXPECT_EQ(warning_count(), 6u);
  FaultReport report;
  EXPECT_TRUE(recent_fault_report(0, report));
  EXPECT_FALSE(recent_fault_report(1, report));
  WarningTally tally;
  ASSERT_TRUE(warning_tally(0, tally));
  EXPECT_EQ(tally.count, 6u);
  EXPECT_STREQ(tally.detail, report.detail);
  EXPECT_EQ(channel_a.current_position, 0.0);
  EXPECT_EQ(channel_b.current_position, 0.0);
}

TEST_F(EbbRateTest, ShorterFramesRaiseTheCeilingAndTheMoveKeepsItsOwnTime) {
  // At 20 µs a channel takes 50,000 steps/s: motor 1's 44,800 1/16 steps/s fit, nothing is
  // slowed, and the move takes its 0.125 s = 6250 frames of 20 µs.
  start(20);
  ASSERT_EQ(host.exchange(kFastLine), "OK\r\n");
  int frames = 0;
  while (channel_a.current_position != 5600 && frames < 100000) {
    host.step();
    ++frames;
  }
  EXPECT_NEAR(frames, 6250, 3);
  EXPECT_EQ(counter("moves_stretched"), 0u);
  EXPECT_EQ(warning_count(), 0u);
}

TEST_F(EbbRateTest, MovesWithinTheRateAreNotTouched) {
  // 1/16 at 40 µs: an EBB motor steps at most once per tick, which the wire always carries.
  // 2500 steps each in 100 ms (25,000 steps/s, the EBB's own limit) take 2500 frames.
  start(40);
  ASSERT_EQ(host.exchange("EM,1,1\r"), "OK\r\n");
  for (int i = 0; i < 10; ++i) host.step();
  ASSERT_EQ(host.exchange("SM,100,2500,-2500\r"), "OK\r\n");
  int frames = 0;
  while ((channel_a.current_position != 2500 || channel_b.current_position != -2500) && frames < 100000) {
    host.step();
    ++frames;
  }
  EXPECT_NEAR(frames, 2500, 2);
  EXPECT_EQ(counter("moves_stretched"), 0u);
  EXPECT_EQ(warning_count(), 0u);
}

}  // namespace
}  // namespace stepdance
