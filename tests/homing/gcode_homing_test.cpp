// `$H` on the G-code interface: error:5 without a Homing; with one it homes the axis and the
// interface's X then reads the homed position.
#include <gtest/gtest.h>

#include <string>

#include "hal_manual.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/homing/homing.hpp"
#include "stepdance/interfaces/gcode/gcode_interface.hpp"
#include "stepdance/motion/channel.hpp"
#include "support/engine_fixture.hpp"
#include "support/fake_byte_stream.hpp"

namespace stepdance {
namespace {

constexpr uint8_t kSwitchPin = 30;
constexpr double kStepsPerMm = 80.0;

class GCodeHomingTest : public test_support::EngineFixture {
 protected:
  void SetUp() override {
    EngineFixture::SetUp();
    channel.set_ratio(1.0, kStepsPerMm);
    ASSERT_EQ(channel.begin(nullptr, SIGNAL_X), Status::kOk);
    gcode.output_x.map(&channel.input_target_position);
    ASSERT_EQ(gcode.begin(&host), Status::kOk);
  }
  /// Carriage 12 mm above a switch at 0: it closes at or below 0.
  double carriage_mm() const {
    return 12.0 + (static_cast<double>(channel.pulses_forward()) - channel.pulses_reverse()) / kStepsPerMm;
  }
  void run_ms(int ms) {
    for (int i = 0; i < ms * 25; ++i) {
      hal_manual::set_pin(kSwitchPin, carriage_mm() <= 1e-9);
      hal_manual::run_frames(1);
      if (i % 5 == 0) dance_loop();
    }
  }

  test_support::FakeByteStream host;
  GCodeInterface gcode;
  Channel channel;
  Homing homing;
};

TEST_F(GCodeHomingTest, WithoutAHomingBlockDollarHIsError5) {
  ASSERT_EQ(dance_start(), Status::kOk);
  run_ms(10);
  host.take();
  host.send("$H\n");
  run_ms(10);
  EXPECT_NE(host.take().find("error:5"), std::string::npos);
}

TEST_F(GCodeHomingTest, DollarHHomesAndTheInterfaceAdoptsTheHomedPosition) {
  ASSERT_EQ(homing.add_axis(kSwitchPin, 0.0, HOMING_DIR_BWD, 20.0f, &channel.input_target_position), Status::kOk);
  ASSERT_EQ(homing.begin(), Status::kOk);
  gcode.set_homing(&homing);
  ASSERT_EQ(dance_start(), Status::kOk);
  run_ms(10);
  host.take();
  host.send("$H\nG91 G1 X1 F600\n");
  run_ms(20);
  EXPECT_TRUE(homing.is_homing());
  EXPECT_EQ(host.take(), "");  // as on Grbl, `$H` is answered when the routine ends
  run_ms(3000);
  EXPECT_TRUE(homing.is_homed());
  EXPECT_EQ(host.take(), "ok\r\nok\r\n");  // then the line after it runs
  run_ms(2000);
  // The switch point is 0, the axis rests a 1 mm pull-off above it, and the relative move queued
  // behind `$H` took it 1 mm further; G-code's X agrees.
  EXPECT_NEAR(carriage_mm(), 2.0, 1.0 / kStepsPerMm);
  EXPECT_NEAR(gcode.output_x.read_absolute(), 2.0, 1.0 / kStepsPerMm);
  host.send("G90 G1 X5 F600\n");
  run_ms(2000);
  EXPECT_NEAR(carriage_mm(), 5.0, 1.0 / kStepsPerMm);
}

TEST_F(GCodeHomingTest, ASwitchThatNeverClosesAnswersDollarHWithAlarm9ThenOk) {
  ASSERT_EQ(homing.add_axis(kSwitchPin, 0.0, HOMING_DIR_BWD, 20.0f, &channel.input_target_position), Status::kOk);
  homing.axis(0).set_timeout_ms(300);  // the switch is never wired: the seek times out
  ASSERT_EQ(homing.begin(), Status::kOk);
  gcode.set_homing(&homing);
  ASSERT_EQ(dance_start(), Status::kOk);
  run_ms(10);
  host.take();
  host.send("$H\n");
  for (int i = 0; i < 500 * 25; ++i) {  // the pin stays low
    hal_manual::run_frames(1);
    if (i % 5 == 0) dance_loop();
  }
  EXPECT_FALSE(homing.is_homed());
  EXPECT_EQ(host.take(), "ALARM:9\r\nok\r\n");
  host.send("G0 X1\n");  // locked until $X or a successful $H, as on Grbl
  run_ms(10);
  EXPECT_EQ(host.take(), "error:9\r\n");
}

}  // namespace
}  // namespace stepdance
