// OutputPort: board checks, driver enable, statistics, carry-over of full frames, pending cancel.
#include "stepdance/io/output_port.hpp"

#include <gtest/gtest.h>

#include "hal_manual.hpp"
#include "stepdance/core/dance.hpp"
#include "support/engine_fixture.hpp"

namespace stepdance {
namespace {

// Bits first..first+count−1 set: the µs slots a pulse or DIR window occupies in a frame.
constexpr uint32_t bits(uint8_t first, uint8_t count) { return ((1u << count) - 1u) << first; }

constexpr uint8_t kOutputAEnablePin = 14;  // Driver Module, active low

class OutputPortTest : public test_support::EngineFixture {
 protected:
  void TearDown() override {
    select_board(kDriverModuleV1);
    EngineFixture::TearDown();
  }
};

TEST_F(OutputPortTest, BasicModuleHasOnlyOutputAAndNoDrivers) {
  select_board(kBasicModuleV1);
  OutputPort a;
  OutputPort b;
  EXPECT_EQ(b.begin(OUTPUT_B), Status::kNoSuchPin);
  EXPECT_FALSE(hal_manual::output_claimed(OUTPUT_B));
  ASSERT_EQ(a.begin(OUTPUT_A), Status::kOk);
  EXPECT_EQ(a.enable_driver(), Status::kNoSuchPin);
  EXPECT_EQ(a.disable_driver(), Status::kNoSuchPin);
  EXPECT_EQ(enable_drivers(), Status::kNoSuchPin);
  EXPECT_FLOAT_EQ(a.read_drive_current_amps(), -1.0f);
  EXPECT_FALSE(a.read_limit_switch());
  EXPECT_EQ(hal_manual::pin_mode(kOutputAEnablePin), hal::PinMode::kInput);  // IO_A1 untouched
}

TEST_F(OutputPortTest, DriverEnableIsActiveLow) {
  OutputPort a;
  ASSERT_EQ(a.begin(OUTPUT_A), Status::kOk);
  EXPECT_STREQ(a.port_name, "OUTPUT A");
  ASSERT_EQ(a.disable_driver(), Status::kOk);
  EXPECT_EQ(hal_manual::pin_mode(kOutputAEnablePin), hal::PinMode::kOutput);
  EXPECT_TRUE(hal_manual::pin_level(kOutputAEnablePin));
  ASSERT_EQ(a.enable_driver(), Status::kOk);
  EXPECT_FALSE(hal_manual::pin_level(kOutputAEnablePin));
  ASSERT_EQ(disable_drivers(), Status::kOk);
  EXPECT_TRUE(hal_manual::pin_level(kOutputAEnablePin));
}

TEST_F(OutputPortTest, ReadsDriveCurrentAndLimitSwitch) {
  OutputPort a;
  ASSERT_EQ(a.begin(OUTPUT_A), Status::kOk);
  hal_manual::set_adc(15, 310);  // VREF of OUTPUT A: 310 / 1023 × 3.3 V = 1.0 V
  EXPECT_FLOAT_EQ(a.read_drive_current_amps(), 1.0f);
  EXPECT_FLOAT_EQ(a.read_drive_current_amps(0.5f), 0.5f);
  EXPECT_FALSE(a.read_limit_switch());
  hal_manual::set_pin(29, true);
  EXPECT_TRUE(a.read_limit_switch());
}

TEST_F(OutputPortTest, ManualTransmitModeLeavesTheFrameToTheSketch) {
  OutputPort a;
  EXPECT_EQ(a.begin(OUTPUT_A, OUTPUT_FRAME_32US, OUTPUT_TRANSMIT_MANUAL), Status::kOk);
  EXPECT_EQ(engine().count(Stage::kOutputPorts), 0u);  // manual: the sketch transmits
}

TEST_F(OutputPortTest, EncodesOneFrameAndCountsPulsesSent) {
  OutputPort a;
  ASSERT_EQ(a.begin(OUTPUT_A), Status::kOk);
  ASSERT_EQ(dance_start(), Status::kOk);
  a.add_signal(SIGNAL_X, DIRECTION_FORWARD);
  a.add_signal(SIGNAL_R, DIRECTION_REVERSE);
  hal_manual::run_frames(1);
  // X: STEP 2..3 µs, DIR 1..4 µs; R (after X's 4 µs slot): STEP 6..9 µs, DIR low.
  EXPECT_EQ(hal_manual::last_frame(OUTPUT_A).step_bits, bits(2, 2) | bits(6, 4));
  EXPECT_EQ(hal_manual::last_frame(OUTPUT_A).dir_bits, bits(1, 4));
  EXPECT_EQ(a.pulses_sent(SIGNAL_X, DIRECTION_FORWARD), 1u);
  EXPECT_EQ(a.pulses_sent(SIGNAL_R, DIRECTION_REVERSE), 1u);
  EXPECT_EQ(a.pulses_sent(SIGNAL_R, DIRECTION_FORWARD), 0u);

  hal_manual::run_frames(2);  // empty frames are still sent every tick
  EXPECT_EQ(hal_manual::frames_written(OUTPUT_A), 3u);
  EXPECT_EQ(hal_manual::last_frame(OUTPUT_A).step_bits, 0u);

  for (int i = 0; i < 3; ++i) {
    a.add_signal(SIGNAL_E, DIRECTION_REVERSE);
    hal_manual::run_frames(1);
  }
  EXPECT_EQ(a.pulses_sent(SIGNAL_E, DIRECTION_REVERSE), 3u);
  EXPECT_EQ(a.pulses_sent(6, DIRECTION_FORWARD), 0u);
}

TEST_F(OutputPortTest, SixSignalsInOneFrameCarryEToTheNextFrameWithPriority) {
  OutputPort a;
  ASSERT_EQ(a.begin(OUTPUT_A, OUTPUT_FRAME_32US, OUTPUT_TRANSMIT_MANUAL), Status::kOk);
  for (uint8_t signal = 0; signal < kNumSignals; ++signal) a.add_signal(signal, DIRECTION_FORWARD);
  a.transmit_frame();
  // Slots of width + 2 µs gap from 2 µs: X 2, Y 6, R 11, T 17, Z 24 (ends at 29); E's 9 µs slot
  // would end past bit 31, so E waits.
  const protocol::FrameWords first = hal_manual::last_frame(OUTPUT_A);
  EXPECT_EQ(first.step_bits, bits(2, 2) | bits(6, 3) | bits(11, 4) | bits(17, 5) | bits(24, 6));
  EXPECT_EQ(first.dir_bits, bits(1, 30));  // the five DIR windows touch: 1..30 µs
  EXPECT_EQ(a.pulses_sent(SIGNAL_E, DIRECTION_FORWARD), 0u);
  EXPECT_EQ(a.pending(SIGNAL_E), 1);
  EXPECT_EQ(a.signals_carried(), 1u);

  // Six more: the carried E goes first, then X, Y, R, T fit beside it; Z waits this time.
  for (uint8_t signal = 0; signal < kNumSignals; ++signal) a.add_signal(signal, DIRECTION_FORWARD);
  a.transmit_frame();
  const protocol::FrameWords second = hal_manual::last_frame(OUTPUT_A);
  EXPECT_EQ(second.step_bits, bits(2, 2) | bits(6, 3) | bits(11, 4) | bits(17, 5) | bits(24, 7));
  EXPECT_EQ(a.pulses_sent(SIGNAL_E, DIRECTION_FORWARD), 1u);
  EXPECT_EQ(a.pulses_sent(SIGNAL_Z, DIRECTION_FORWARD), 1u);
  EXPECT_EQ(a.pending(SIGNAL_Z), 1);
  EXPECT_EQ(a.pending(SIGNAL_E), 1);
  EXPECT_EQ(a.signals_carried(), 2u);

  a.transmit_frame();  // Z carried first, then E fits: 8 + 9 µs
  EXPECT_EQ(hal_manual::last_frame(OUTPUT_A).step_bits, bits(2, 6) | bits(10, 7));
  EXPECT_EQ(a.pending(SIGNAL_Z), 0);
  EXPECT_EQ(a.pending(SIGNAL_E), 0);
  EXPECT_EQ(a.pulses_sent(SIGNAL_E, DIRECTION_FORWARD), 2u);
  EXPECT_EQ(a.pulses_sent(SIGNAL_Z, DIRECTION_FORWARD), 2u);
}

TEST_F(OutputPortTest, ForwardAndReversePendingOnOneSignalCancel) {
  OutputPort a;
  ASSERT_EQ(a.begin(OUTPUT_A, OUTPUT_FRAME_32US, OUTPUT_TRANSMIT_MANUAL), Status::kOk);
  a.add_signal(SIGNAL_Y, DIRECTION_FORWARD);
  a.add_signal(SIGNAL_Y, DIRECTION_REVERSE);
  EXPECT_EQ(a.pending(SIGNAL_Y), 0);
  a.transmit_frame();
  EXPECT_EQ(hal_manual::last_frame(OUTPUT_A).step_bits, 0u);
  EXPECT_EQ(a.pulses_sent(SIGNAL_Y, DIRECTION_FORWARD), 0u);
  EXPECT_EQ(a.pulses_sent(SIGNAL_Y, DIRECTION_REVERSE), 0u);

  // A carried E reversed by the next frame's channel: net zero, nothing is sent.
  for (uint8_t signal = 0; signal < kNumSignals; ++signal) a.add_signal(signal, DIRECTION_FORWARD);
  a.transmit_frame();
  EXPECT_EQ(a.pending(SIGNAL_E), 1);
  a.add_signal(SIGNAL_E, DIRECTION_REVERSE);
  a.transmit_frame();
  EXPECT_EQ(hal_manual::last_frame(OUTPUT_A).step_bits, 0u);
  EXPECT_EQ(a.pulses_sent(SIGNAL_E, DIRECTION_FORWARD), 0u);
  EXPECT_EQ(a.pulses_sent(SIGNAL_E, DIRECTION_REVERSE), 0u);
}

TEST_F(OutputPortTest, BeginStartsWithEmptyStatisticsAndNothingPending) {
  OutputPort a;
  ASSERT_EQ(a.begin(OUTPUT_A), Status::kOk);
  ASSERT_EQ(dance_start(), Status::kOk);
  a.add_signal(SIGNAL_X, DIRECTION_FORWARD);
  hal_manual::run_frames(1);
  a.add_signal(SIGNAL_Y, DIRECTION_REVERSE);  // left pending: no frame runs before begin()
  ASSERT_EQ(a.pulses_sent(SIGNAL_X, DIRECTION_FORWARD), 1u);

  stepdance::hal_manual::reset();  // frees the port claim, as a fresh boot would
  ASSERT_EQ(a.begin(OUTPUT_A), Status::kOk);
  EXPECT_EQ(a.pulses_sent(SIGNAL_X, DIRECTION_FORWARD), 0u);
  EXPECT_EQ(a.pending(SIGNAL_Y), 0);
  EXPECT_EQ(a.signals_carried(), 0u);
}

TEST_F(OutputPortTest, ASecondObjectOnAPortRetiresTheFirst) {
  OutputPort first;
  OutputPort second;
  ASSERT_EQ(first.begin(OUTPUT_B), Status::kOk);
  EXPECT_EQ(second.begin(OUTPUT_B), Status::kBusy);  // the hardware port is claimed

  stepdance::hal_manual::reset();  // the claim is gone; the first object is still registered
  ASSERT_EQ(second.begin(OUTPUT_B), Status::kOk);
  EXPECT_EQ(first.port_index(), 255);
  EXPECT_EQ(second.port_index(), OUTPUT_B);
  EXPECT_EQ(engine().count(Stage::kOutputPorts), 1u);
}

TEST_F(OutputPortTest, StepNowIsSentWithTheNextFrame) {
  OutputPort d;
  ASSERT_EQ(d.begin(OUTPUT_D), Status::kOk);
  EXPECT_STREQ(d.port_name, "OUTPUT D");
  ASSERT_EQ(dance_start(), Status::kOk);
  d.step_now(DIRECTION_FORWARD);  // default signal: E
  EXPECT_EQ(hal_manual::frames_written(OUTPUT_D), 0u);
  hal_manual::run_frames(1);
  EXPECT_EQ(hal_manual::last_frame(OUTPUT_D).step_bits, bits(2, 7));
  EXPECT_EQ(hal_manual::last_frame(OUTPUT_D).dir_bits, bits(1, 9));
  EXPECT_EQ(d.pulses_sent(SIGNAL_E, DIRECTION_FORWARD), 1u);
}

// Idle timeout of 2 ms = 50 frames: the driver goes off after 50 quiet frames and comes back
// in the frame a pulse is encoded (it plays on the wire the frame after). Off by default.
TEST_F(OutputPortTest, AnIdleDriverIsDisabledAndWakesOnTheNextPulse) {
  OutputPort a;
  ASSERT_EQ(a.begin(OUTPUT_A), Status::kOk);
  ASSERT_EQ(a.enable_driver(), Status::kOk);
  ASSERT_EQ(dance_start(), Status::kOk);
  hal_manual::run_frames(500);
  EXPECT_FALSE(hal_manual::pin_level(kOutputAEnablePin));  // no timeout set: stays enabled
  a.set_driver_idle_timeout_ms(2);
  hal_manual::run_frames(49);
  EXPECT_FALSE(hal_manual::pin_level(kOutputAEnablePin));
  hal_manual::run_frames(1);
  EXPECT_TRUE(hal_manual::pin_level(kOutputAEnablePin));  // 50 quiet frames: disabled
  EXPECT_TRUE(a.driver_idle());
  a.add_signal(SIGNAL_E, DIRECTION_FORWARD);
  hal_manual::run_frames(1);
  EXPECT_FALSE(hal_manual::pin_level(kOutputAEnablePin));  // enabled with the frame that steps
  EXPECT_FALSE(a.driver_idle());
  EXPECT_EQ(a.pulses_sent(SIGNAL_E, DIRECTION_FORWARD), 1u);
}

TEST_F(OutputPortTest, TheIdleTimeoutNeverWakesADriverTheSketchDisabled) {
  OutputPort a;
  ASSERT_EQ(a.begin(OUTPUT_A), Status::kOk);
  ASSERT_EQ(a.disable_driver(), Status::kOk);
  set_drivers_idle_timeout_ms(1);
  ASSERT_EQ(dance_start(), Status::kOk);
  a.add_signal(SIGNAL_E, DIRECTION_FORWARD);
  hal_manual::run_frames(100);
  EXPECT_TRUE(hal_manual::pin_level(kOutputAEnablePin));  // still disabled, as the sketch said
  EXPECT_FALSE(a.driver_idle());
  ASSERT_EQ(a.enable_driver(), Status::kOk);  // the sketch's enable ends any idle state too
  hal_manual::run_frames(25);
  EXPECT_TRUE(hal_manual::pin_level(kOutputAEnablePin));  // 1 ms of quiet: idle again
  set_drivers_idle_timeout_ms(0);                         // turning the timeout off brings the driver back
  EXPECT_FALSE(hal_manual::pin_level(kOutputAEnablePin));
}

}  // namespace
}  // namespace stepdance
