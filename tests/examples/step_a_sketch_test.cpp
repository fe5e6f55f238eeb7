// Compiles the real StepASketch.ino against the public API and checks its motion on the manual
// backend: knob counts in, step pulses out of ports A/B, pen moves from the D1 button.
#include <gtest/gtest.h>

#include "Arduino.h"
#include "arduino_manual.hpp"
#include "hal_manual.hpp"
#include "support/engine_fixture.hpp"

#include "../../examples/StepASketch/StepASketch.ino"

namespace {

using stepdance::hal_manual::run_frames;

constexpr uint8_t kPortA = 0, kPortB = 1, kPortC = 2;
constexpr uint8_t kButtonPin = 28;  // D1 on the Driver Module

// Runs frames in 1 ms slices, calling the sketch's loop() after each, as the real board does.
void run_ms(uint32_t ms) {
  for (uint32_t i = 0; i < ms; ++i) {
    run_frames(25);
    loop();
  }
}

uint32_t pulses(const OutputPort& port, uint8_t direction) { return port.pulses_sent(SIGNAL_E, direction); }

class StepASketchTest : public stepdance::test_support::EngineFixture {
 protected:
  void SetUp() override {
    EngineFixture::SetUp();
    stepdance::arduino_manual::reset();
    stepdance::arduino::reset_state();
    setup();
  }
};

TEST_F(StepASketchTest, StartsTheEngineAndEnablesTheDrivers) {
  EXPECT_TRUE(stepdance::engine().running());
  EXPECT_FALSE(stepdance::hal_manual::pin_level(14));  // OUTPUT A ENABLE, active low
  EXPECT_FALSE(stepdance::hal_manual::pin_level(13));  // OUTPUT B ENABLE
  EXPECT_FALSE(stepdance::hal_manual::pin_level(39));  // OUTPUT C ENABLE
}

TEST_F(StepASketchTest, KnobOneMovesBothMotorsAlongX) {
  // +100 counts on an inverted 0.01 mm/count knob: x = -1 mm. CoreXY: a = b = -1 mm = -80 steps.
  // Both channels invert their output, so 80 pulses with DIR high on each port.
  const double x_before_mm = axidraw_kinematics.input_x.read(ABSOLUTE);  // globals outlive a test
  stepdance::hal_manual::set_quadrature(0, 100);
  run_ms(10);
  EXPECT_EQ(pulses(output_a, DIRECTION_FORWARD), 80u);
  EXPECT_EQ(pulses(output_a, DIRECTION_REVERSE), 0u);
  EXPECT_EQ(pulses(output_b, DIRECTION_FORWARD), 80u);
  EXPECT_EQ(pulses(output_b, DIRECTION_REVERSE), 0u);
  EXPECT_DOUBLE_EQ(axidraw_kinematics.input_x.read(ABSOLUTE) - x_before_mm, -1.0);
}

TEST_F(StepASketchTest, KnobTwoMovesTheMotorsInOppositeDirections) {
  // +50 counts on knob 2: y = -0.5 mm, so a = -40 steps and b = +40 steps (then inverted).
  stepdance::hal_manual::set_quadrature(1, 50);
  run_ms(10);
  EXPECT_EQ(pulses(output_a, DIRECTION_FORWARD), 40u);
  EXPECT_EQ(pulses(output_b, DIRECTION_REVERSE), 40u);
  EXPECT_EQ(pulses(output_a, DIRECTION_REVERSE) + pulses(output_b, DIRECTION_FORWARD), 0u);
}

TEST_F(StepASketchTest, ButtonTogglesThePenDownAndUp) {
  // Press: pen goes to -200 servo steps at 2000 steps/s (0.1 s); the next press lifts it to +200.
  stepdance::hal_manual::set_pin(kButtonPin, true);
  run_ms(60);
  stepdance::hal_manual::set_pin(kButtonPin, false);
  run_ms(200);
  EXPECT_EQ(pulses(output_c, DIRECTION_REVERSE), 200u);
  EXPECT_EQ(pulses(output_c, DIRECTION_FORWARD), 0u);

  stepdance::hal_manual::set_pin(kButtonPin, true);
  run_ms(60);
  stepdance::hal_manual::set_pin(kButtonPin, false);
  run_ms(250);
  EXPECT_EQ(pulses(output_c, DIRECTION_FORWARD), 400u);  // from -200 to +200
  EXPECT_DOUBLE_EQ(channel_z.current_position, 200.0);
}

TEST_F(StepASketchTest, ReportsLoadOncePerSecondOnSerial) {
  // The manual backend's frames cost 0 cycles, so the peak load prints as Print's default
  // two-digit float, "0.00", followed by the "\r\n" of println.
  stepdance::hal_manual::take_console_output();
  run_ms(2100);
  EXPECT_EQ(stepdance::hal_manual::take_console_output(), "CPU peak load: 0.00\r\nCPU peak load: 0.00\r\n");
}

}  // namespace
