// One steps/mm for G-code: at dance_start the interface takes $100–$102 from the channels its X,
// Y and Z drive (through a kinematics or directly), as the EBB takes its ratio; a sketch value
// that disagrees is refused then, with both values named on the fault path.
#include <gtest/gtest.h>

#include <string.h>

#include <string>

#include "hal_manual.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/core/fault.hpp"
#include "stepdance/interfaces/gcode/gcode_interface.hpp"
#include "stepdance/motion/channel.hpp"
#include "stepdance/motion/kinematics_core_xy.hpp"
#include "support/engine_fixture.hpp"
#include "support/fake_byte_stream.hpp"

namespace stepdance {
namespace {

class GcodeStepsPerMm : public test_support::EngineFixture {
 protected:
  /// G-code X, Y → CoreXY → channels a and b at `xy_steps_per_mm`; Z → channel z directly.
  void build(double xy_steps_per_mm, double z_steps_per_mm) {
    for (Channel* channel : {&channel_a, &channel_b, &channel_z}) ASSERT_EQ(channel->begin(), Status::kOk);
    channel_a.set_ratio(1.0, xy_steps_per_mm);
    channel_b.set_ratio(1.0, xy_steps_per_mm);
    channel_z.set_ratio(1.0, z_steps_per_mm);
    ASSERT_EQ(gcode.begin(&host), Status::kOk);
    gcode.output_x.map(&kinematics.input_x);
    gcode.output_y.map(&kinematics.input_y);
    gcode.output_z.map(&channel_z.input_target_position);
    ASSERT_EQ(kinematics.begin(), Status::kOk);
    kinematics.output_a.map(&channel_a.input_target_position);
    kinematics.output_b.map(&channel_b.input_target_position);
  }
  std::string settings_report() {
    host.take();
    host.send("$$\n");
    for (int i = 0; i < 20; ++i) {
      dance_loop();
      hal_manual::run_frames(1);
    }
    return host.take();
  }

  test_support::FakeByteStream host;
  GCodeInterface gcode;
  KinematicsCoreXY kinematics;
  Channel channel_a, channel_b, channel_z;
};

TEST_F(GcodeStepsPerMm, TheChannelsGiveDollarHundredToHundredTwo) {
  build(2032.0 / 25.4, 50.0);  // an AxiDraw's belts: 80 steps/mm
  ASSERT_EQ(dance_start(), Status::kOk);
  EXPECT_EQ(fault_reason(), FaultReason::kNone);
  EXPECT_DOUBLE_EQ(gcode.settings().value(100), 80.0);
  EXPECT_DOUBLE_EQ(gcode.settings().value(101), 80.0);
  EXPECT_DOUBLE_EQ(gcode.settings().value(102), 50.0);
  const std::string report = settings_report();
  EXPECT_NE(report.find("$100=80.000\r\n$101=80.000\r\n$102=50.000\r\n"), std::string::npos) << report;
}

TEST_F(GcodeStepsPerMm, AnAgreeingSketchValueIsAccepted) {
  build(80.0, 50.0);
  ASSERT_TRUE(gcode.settings().set_from_sketch(100, 80));
  ASSERT_TRUE(gcode.settings().set_from_sketch(102, 50));
  EXPECT_EQ(dance_start(), Status::kOk);
  EXPECT_EQ(fault_reason(), FaultReason::kNone);
}

TEST_F(GcodeStepsPerMm, ADisagreeingSketchValueIsAFaultNamingBoth) {
  build(40.0, 50.0);
  ASSERT_TRUE(gcode.settings().set_from_sketch(101, 80));
  EXPECT_NE(dance_start(), Status::kOk);
  EXPECT_EQ(fault_reason(), FaultReason::kBadConfiguration);
  const std::string detail = fault_detail();
  EXPECT_NE(detail.find("$101"), std::string::npos) << detail;
  EXPECT_NE(detail.find("80"), std::string::npos) << detail;
  EXPECT_NE(detail.find("40"), std::string::npos) << detail;
}

TEST_F(GcodeStepsPerMm, WithoutChannelsTheSketchValueStays) {
  ASSERT_EQ(gcode.begin(&host), Status::kOk);
  ASSERT_TRUE(gcode.settings().set_from_sketch(100, 123));
  ASSERT_EQ(dance_start(), Status::kOk);
  EXPECT_DOUBLE_EQ(gcode.settings().value(100), 123.0);
  EXPECT_DOUBLE_EQ(gcode.settings().value(101), 0.0);
}

}  // namespace
}  // namespace stepdance
