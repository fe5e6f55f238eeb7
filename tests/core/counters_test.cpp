// Named counters: every registered block visited once; ports and kinematics report theirs.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "hal_manual.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/core/engine.hpp"
#include "stepdance/io/analog_input.hpp"
#include "stepdance/io/output_port.hpp"
#include "stepdance/motion/channel.hpp"
#include "stepdance/motion/kinematics_five_bar.hpp"
#include "support/engine_fixture.hpp"

namespace stepdance {
namespace {

class Collector : public CounterSink {
 public:
  void counter(const char* name, uint64_t value) override { values[name] = value; }
  std::map<std::string, uint64_t> values;
};

class CountersTest : public test_support::EngineFixture {};

TEST_F(CountersTest, EveryBlockIsVisitedOnceEvenInSeveralStages) {
  AnalogInput pot;  // registers in the kilohertz and loop stages
  ASSERT_EQ(pot.begin(kDriverModuleV1.io_a[0]), Status::kOk);
  OutputPort port;
  ASSERT_EQ(port.begin(OUTPUT_A), Status::kOk);
  std::map<std::string, int> visits;
  engine().for_each_block(
      [](Block* block, void* context) { ++(*static_cast<std::map<std::string, int>*>(context))[block->type_name()]; },
      &visits);
  EXPECT_EQ(visits, (std::map<std::string, int>{{"AnalogInput", 1}, {"OutputPort", 1}}));
}

TEST_F(CountersTest, AnOutputPortCountsWhatItSent) {
  OutputPort port;
  Channel channel;
  ASSERT_EQ(port.begin(OUTPUT_B), Status::kOk);
  ASSERT_EQ(channel.begin(&port, SIGNAL_E), Status::kOk);
  channel.input_target_position.write(5, ABSOLUTE);  // 5 steps forward, one a frame
  ASSERT_EQ(dance_start(), Status::kOk);
  hal_manual::run_frames(20);
  Collector collected;
  port.report_counters(collected);
  EXPECT_EQ(collected.values["port"], 1u);
  EXPECT_EQ(collected.values["sent_e_forward"], port.pulses_sent(SIGNAL_E, DIRECTION_FORWARD));
  EXPECT_EQ(collected.values["sent_e_forward"], 5u);
  EXPECT_EQ(collected.values["sent_e_reverse"], 0u);
  EXPECT_EQ(collected.values.size(), 14u);  // port, carried, 6 signals × 2 directions
}

TEST_F(CountersTest, FiveBarKinematicsReportUnreachablePoses) {
  KinematicsFiveBarInverse inverse;
  ASSERT_EQ(inverse.begin(60, 145.75, 134, 169, 178.3, 28.82, 2.9019f), Status::kOk);
  inverse.input_x.write(5000, ABSOLUTE);  // far out of reach
  ASSERT_EQ(dance_start(), Status::kOk);
  hal_manual::run_frames(3);
  Collector collected;
  inverse.report_counters(collected);
  EXPECT_EQ(collected.values["unreachable"], inverse.unreachable_count());
  EXPECT_GE(collected.values["unreachable"], 1u);
}

}  // namespace
}  // namespace stepdance
