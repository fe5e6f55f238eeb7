// AnalogInput: floor/ceiling map, clamp, deadband, invert, mapped parameters and loop callbacks.
#include "stepdance/io/analog_input.hpp"

#include <gtest/gtest.h>

#include "hal_manual.hpp"
#include "stepdance/core/dance.hpp"
#include "support/engine_fixture.hpp"

namespace stepdance {
namespace {

constexpr uint8_t kPin = 24;  // IO_A1 on the Driver Module

int callback_calls = 0;
void count_callback() { ++callback_calls; }

class AnalogInputTest : public test_support::EngineFixture {
 protected:
  void SetUp() override {
    EngineFixture::SetUp();
    callback_calls = 0;
  }
  // Sets the pin's conversion and returns what read() makes of it.
  float read_at(AnalogInput& input, uint16_t raw) {
    hal_manual::set_adc(kPin, raw);
    return input.read();
  }
};

TEST_F(AnalogInputTest, DefaultMapIsTheRawCount) {
  AnalogInput input;
  ASSERT_EQ(input.begin(kPin), Status::kOk);
  EXPECT_FLOAT_EQ(read_at(input, 0), 0.0f);
  EXPECT_FLOAT_EQ(read_at(input, 512), 512.0f);
  EXPECT_FLOAT_EQ(read_at(input, 1023), 1023.0f);
  EXPECT_EQ(input.read_raw(), 1023);
}

TEST_F(AnalogInputTest, FloorAndCeilingMapLinearlyAndClamp) {
  AnalogInput input;
  ASSERT_EQ(input.begin(kPin), Status::kOk);
  input.set_floor(0, 23);
  input.set_ceiling(10, 1023);                // 1000 counts for 10 units
  EXPECT_FLOAT_EQ(read_at(input, 10), 0.0f);  // below the floor count: clamped
  EXPECT_FLOAT_EQ(read_at(input, 23), 0.0f);
  EXPECT_FLOAT_EQ(read_at(input, 123), 1.0f);
  EXPECT_FLOAT_EQ(read_at(input, 523), 5.0f);
  EXPECT_FLOAT_EQ(read_at(input, 1023), 10.0f);

  input.set_ceiling(10, 823);  // 800 counts for 10 units
  EXPECT_FLOAT_EQ(read_at(input, 423), 5.0f);
  EXPECT_FLOAT_EQ(read_at(input, 1000), 10.0f);  // 12.2125 unclamped
}

TEST_F(AnalogInputTest, FloorAboveCeilingGivesAFallingMapThatStillClamps) {
  AnalogInput input;
  ASSERT_EQ(input.begin(kPin), Status::kOk);
  input.set_floor(10, 0);
  input.set_ceiling(-10, 1000);
  EXPECT_FLOAT_EQ(read_at(input, 0), 10.0f);
  EXPECT_FLOAT_EQ(read_at(input, 250), 5.0f);
  EXPECT_FLOAT_EQ(read_at(input, 500), 0.0f);
  EXPECT_FLOAT_EQ(read_at(input, 1000), -10.0f);
  EXPECT_FLOAT_EQ(read_at(input, 1023), -10.0f);  // −10.46 unclamped
}

TEST_F(AnalogInputTest, CalibrationFieldsMirrorTheMapSettings) {
  AnalogInput knob;
  knob.set_floor(-10, 100);
  knob.set_ceiling(10, 900);  // 20 over 800 counts: slope 0.025, through (100, −10)
  EXPECT_FLOAT_EQ(knob.conversion_slope_1, 0.025f);
  EXPECT_FLOAT_EQ(knob.conversion_intercept_1, -12.5f);
  EXPECT_FLOAT_EQ(knob.conversion_slope_2, 0.025f);
  knob.set_deadband(0, 500, 20);  // band 490..510 holds 0
  EXPECT_EQ(knob.adc_deadband_lower, 490);
  EXPECT_EQ(knob.adc_deadband_upper, 510);
  EXPECT_FLOAT_EQ(knob.conversion_slope_1, 10.0f / 390.0f);  // (100, −10) to (490, 0)
  EXPECT_FLOAT_EQ(knob.conversion_slope_2, 10.0f / 390.0f);  // (510, 0) to (900, 10)
  EXPECT_FLOAT_EQ(knob.conversion_intercept_2, -510.0f * 10.0f / 390.0f);
  knob.clear_deadband();
  EXPECT_EQ(knob.adc_deadband_upper, 0);
}

TEST_F(AnalogInputTest, DeadbandHoldsItsValueAndSplitsTheMapInTwo) {
  AnalogInput input;
  ASSERT_EQ(input.begin(kPin), Status::kOk);
  // The harmonograph's scale knob: 0..20, held at 1 for counts 507..511.
  input.set_floor(0);
  input.set_ceiling(20);
  input.set_deadband(1, 509, 4);
  EXPECT_DOUBLE_EQ(input.value_at(0), 0.0);
  EXPECT_DOUBLE_EQ(input.value_at(169), 1.0 / 3.0);  // 169 / 507 of the way to 1
  EXPECT_DOUBLE_EQ(input.value_at(506), 1.0 - 1.0 / 507.0);
  EXPECT_DOUBLE_EQ(input.value_at(507), 1.0);
  EXPECT_DOUBLE_EQ(input.value_at(509), 1.0);
  EXPECT_DOUBLE_EQ(input.value_at(511), 1.0);
  EXPECT_DOUBLE_EQ(input.value_at(767), 10.5);  // 1 + 256 × 19 / 512
  EXPECT_DOUBLE_EQ(input.value_at(1023), 20.0);

  input.clear_deadband();
  EXPECT_DOUBLE_EQ(input.value_at(767), 767.0 * 20.0 / 1023.0);
}

TEST_F(AnalogInputTest, DeadbandNearTheEndsDoesNotWrap) {
  AnalogInput input;
  ASSERT_EQ(input.begin(kPin), Status::kOk);
  input.set_floor(-1);
  input.set_ceiling(1);
  input.set_deadband(0, 1, 4);  // band −1..3: the original's uint16 bound wrapped to 65535
  EXPECT_DOUBLE_EQ(input.value_at(0), 0.0);
  EXPECT_DOUBLE_EQ(input.value_at(3), 0.0);
  EXPECT_DOUBLE_EQ(input.value_at(513), 0.5);  // 510 of the 1020 counts above the band
  EXPECT_DOUBLE_EQ(input.value_at(1023), 1.0);

  input.set_deadband(0, 1022, 1);  // width 1 counts as 2: band 1021..1023
  EXPECT_DOUBLE_EQ(input.value_at(1023), 0.0);
  EXPECT_DOUBLE_EQ(input.value_at(1021), 0.0);
  EXPECT_DOUBLE_EQ(input.value_at(0), -1.0);
  EXPECT_NEAR(input.value_at(1020), -1.0 / 1021.0, 1e-15);  // −1 + 1020/1021: cancellation
}

TEST_F(AnalogInputTest, DeadbandHereUsesTheCurrentConversion) {
  AnalogInput input;
  ASSERT_EQ(input.begin(kPin), Status::kOk);
  input.set_floor(-50);
  input.set_ceiling(50);
  hal_manual::set_adc(kPin, 600);
  input.set_deadband_here(0, 50);  // band 575..625
  EXPECT_DOUBLE_EQ(input.value_at(600), 0.0);
  EXPECT_DOUBLE_EQ(input.value_at(575), 0.0);
  EXPECT_DOUBLE_EQ(input.value_at(625), 0.0);
  EXPECT_DOUBLE_EQ(input.value_at(115), -40.0);  // −50 + 115 × 50 / 575
  EXPECT_DOUBLE_EQ(input.value_at(0), -50.0);
  EXPECT_DOUBLE_EQ(input.value_at(1023), 50.0);
}

TEST_F(AnalogInputTest, DeadbandHereWaitsForTheFirstConversion) {
  AnalogInput input;
  ASSERT_EQ(input.begin(kPin), Status::kOk);
  input.set_floor(-10);
  input.set_ceiling(10, 1000);
  input.set_deadband_here(0, 4);  // nothing converted yet: no band until the first sample
  EXPECT_DOUBLE_EQ(input.value_at(700), 4.0);
  ASSERT_EQ(dance_start(), Status::kOk);
  hal_manual::set_adc(kPin, 700);
  hal_manual::run_frames(25);  // one kilohertz tick captures the centre
  EXPECT_DOUBLE_EQ(input.value_at(700), 0.0);
  EXPECT_DOUBLE_EQ(input.value_at(702), 0.0);
  EXPECT_DOUBLE_EQ(input.value_at(851), 5.0);  // 149 of the 298 counts from 702 to 1000
}

TEST_F(AnalogInputTest, InvertNegatesTheClampedOutput) {
  AnalogInput input;
  ASSERT_EQ(input.begin(kPin), Status::kOk);
  input.set_floor(0);
  input.set_ceiling(10, 1000);
  input.invert();
  EXPECT_FLOAT_EQ(read_at(input, 250), -2.5f);
  EXPECT_FLOAT_EQ(read_at(input, 1023), -10.0f);  // clamped first, then negated
  EXPECT_FLOAT_EQ(read_at(input, 0), 0.0f);
  input.invert();  // invert() toggles
  EXPECT_FLOAT_EQ(read_at(input, 250), 2.5f);
}

TEST_F(AnalogInputTest, MappedParametersAreWrittenByTheKilohertzStage) {
  AnalogInput speed_knob;
  AnalogInput radius_knob;
  ControlParameter speed = -1.0f;
  DecimalPosition radius = -1.0;
  ASSERT_EQ(speed_knob.begin(kPin), Status::kOk);
  ASSERT_EQ(radius_knob.begin(25), Status::kOk);
  speed_knob.set_floor(0, 25);
  speed_knob.set_ceiling(2.75, 1020);
  speed_knob.map(&speed);
  radius_knob.set_ceiling(20, 1000);
  radius_knob.map(&radius);
  hal_manual::set_adc(kPin, 423);  // 398 of 995 counts → 1.1
  hal_manual::set_adc(25, 100);
  ASSERT_EQ(dance_start(), Status::kOk);

  hal_manual::run_frames(24);
  EXPECT_FLOAT_EQ(speed, -1.0f);  // no kilohertz tick yet
  EXPECT_DOUBLE_EQ(radius, -1.0);
  hal_manual::run_frames(1);
  EXPECT_FLOAT_EQ(speed, 1.1f);
  EXPECT_DOUBLE_EQ(radius, 2.0);

  hal_manual::set_adc(kPin, 1023);
  hal_manual::run_frames(25);
  EXPECT_FLOAT_EQ(speed, 2.75f);
}

TEST_F(AnalogInputTest, CallbackRunsOnlyFromTheLoopAfterNewConversions) {
  AnalogInput input;
  ASSERT_EQ(input.begin(kPin), Status::kOk);
  input.set_callback(&count_callback);
  ASSERT_EQ(dance_start(), Status::kOk);

  dance_loop();
  EXPECT_EQ(callback_calls, 0);  // nothing converted since begin
  hal_manual::set_adc(kPin, 10);
  hal_manual::run_frames(100);  // four kilohertz ticks, no callback there
  EXPECT_EQ(callback_calls, 0);
  dance_loop();
  EXPECT_EQ(callback_calls, 1);
  dance_loop();
  EXPECT_EQ(callback_calls, 1);
  hal_manual::set_adc(kPin, 11);
  hal_manual::set_adc(kPin, 12);
  dance_loop();
  EXPECT_EQ(callback_calls, 2);  // one call per loop pass that saw new conversions
}

TEST_F(AnalogInputTest, PinWithoutAnAdcIsRefused) {
  AnalogInput input;
  EXPECT_EQ(input.begin(200), Status::kNoSuchPin);
  EXPECT_EQ(engine().count(Stage::kKilohertz), 0u);
  EXPECT_EQ(engine().count(Stage::kLoop), 0u);
  EXPECT_EQ(input.read_raw(), 0);
}

}  // namespace
}  // namespace stepdance
