// One steps/mm on the EBB path: the board takes it from the channels its x and y reach, so one
// EBB 1/16 step is one channel step whatever the sketch's ratio; a set_ratio_xy() that disagrees
// with them is refused when the engine starts, with the reason on the fault path.
#include <gtest/gtest.h>

#include <string.h>

#include "interfaces/ebb_test_host.hpp"
#include "stepdance/core/fault.hpp"
#include "stepdance/motion/channel.hpp"
#include "stepdance/motion/kinematics_core_xy.hpp"

namespace stepdance {
namespace {

class EbbRatioTest : public test_support::EngineFixture {
 protected:
  /// Eibotboard → CoreXY → channels a and b at `steps_per_mm` (world mm per channel step).
  void build(double steps_per_mm) {
    ASSERT_EQ(channel_a.begin(), Status::kOk);
    ASSERT_EQ(channel_b.begin(), Status::kOk);
    channel_a.set_ratio(1.0, steps_per_mm);
    channel_b.set_ratio(1.0, steps_per_mm);
    ASSERT_EQ(ebb.begin(&link), Status::kOk);
    ebb.output_x.map(&kinematics.input_x);
    ebb.output_y.map(&kinematics.input_y);
    ASSERT_EQ(kinematics.begin(), Status::kOk);
    kinematics.output_a.map(&channel_a.input_target_position);
    kinematics.output_b.map(&channel_b.input_target_position);
  }
  void run(int frames) {
    for (int i = 0; i < frames; ++i) host.step();
  }

  test_support::FakeByteStream link;
  Eibotboard ebb;
  KinematicsCoreXY kinematics;
  Channel channel_a;
  Channel channel_b;
  test_support::EbbHost host{link};
};

TEST_F(EbbRatioTest, TheChannelsRatioIsTheBoardsWhateverItIs) {
  for (const double steps_per_mm : {80.0, 2874.0 / 25.4, 100.0}) {
    SCOPED_TRACE(steps_per_mm);
    test_support::reset_global_state();
    build(steps_per_mm);
    ASSERT_EQ(dance_start(), Status::kOk);
    // 1/16: motor 1 takes 1234 steps, motor 2 −321; each channel follows its motor step for step.
    ASSERT_EQ(host.exchange("SM,200,1234,-321\r"), "OK\r\n");
    run(6000);
    EXPECT_EQ(channel_a.current_position, 1234);
    EXPECT_EQ(channel_b.current_position, -321);
    EXPECT_NEAR(ebb.output_x.read_absolute(), (1234 - 321) / 2.0 / steps_per_mm, 1e-9);
    ASSERT_EQ(host.exchange("EM,2,2\r"), "OK\r\n");  // 1/8: one step is two channel steps
    ASSERT_EQ(host.exchange("SM,200,-500,100\r"), "OK\r\n");
    run(6000);
    EXPECT_EQ(channel_a.current_position, 1234 - 1000);
    EXPECT_EQ(channel_b.current_position, -321 + 200);
    engine().stop();
  }
}

TEST_F(EbbRatioTest, AnAgreeingSetRatioXyIsAccepted) {
  build(80.0);
  ebb.set_ratio_xy(25.4, 2032);  // what AxiDraw sketches wrote
  EXPECT_EQ(dance_start(), Status::kOk);
  EXPECT_EQ(fault_reason(), FaultReason::kNone);
}

TEST_F(EbbRatioTest, ADisagreeingSetRatioXyIsRefusedAtStart) {
  build(80.0);
  ebb.set_ratio_xy(25.4, 2874);  // the original library's EBB figure beside 80 steps/mm channels
  EXPECT_NE(dance_start(), Status::kOk);
  EXPECT_EQ(fault_reason(), FaultReason::kBadConfiguration);
  EXPECT_NE(strstr(fault_detail(), "set_ratio_xy"), nullptr) << fault_detail();
}

TEST_F(EbbRatioTest, ChannelsThatDisagreeWithEachOtherAreRefusedAtStart) {
  build(80.0);
  channel_b.set_ratio(1.0, 100.0);
  EXPECT_NE(dance_start(), Status::kOk);
  EXPECT_EQ(fault_reason(), FaultReason::kBadConfiguration);
}

TEST_F(EbbRatioTest, WithoutChannelsTheBoardKeepsItsOwnRatio) {
  // Nothing downstream to agree with: set_ratio_xy (or 80 steps/mm) gives the outputs' mm.
  ebb.set_kinematics(EBB_KINEMATICS_XY);
  ebb.set_ratio_xy(1, 100);
  ASSERT_EQ(ebb.begin(&link), Status::kOk);
  ASSERT_EQ(dance_start(), Status::kOk);
  ASSERT_EQ(host.exchange("SM,10,50,-20\r"), "OK\r\n");
  run(500);
  EXPECT_NEAR(ebb.output_x.read_absolute(), 0.5, 1e-12);
  EXPECT_NEAR(ebb.output_y.read_absolute(), -0.2, 1e-12);
}

}  // namespace
}  // namespace stepdance
