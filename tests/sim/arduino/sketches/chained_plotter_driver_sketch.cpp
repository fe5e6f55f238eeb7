// Compiles examples/ChainedPlotterDriver/ChainedPlotterDriver.ino on the manual backend and checks
// that X/Y pulses received on INPUT A move the AxiDraw's motors, and that D1 toggles the pen.
// (Its own executable: the sketch defines the global setup() and loop().)
#include <gtest/gtest.h>

#include "../arduino_fixture.hpp"
#include "stepdance/protocol/frame_encoder.hpp"
#include "stepdance/protocol/frame_reader.hpp"

#include "../../../../examples/ChainedPlotterDriver/ChainedPlotterDriver.ino"

namespace {

using stepdance::hal_manual::inject_pulse;
using stepdance::hal_manual::run_frames;
using stepdance::protocol::CapturedPulse;

constexpr uint8_t kInputA = 0;
constexpr uint8_t kButtonPin = 28;     // D1 on the Driver Module
constexpr uint32_t kTicksPerUs = 150;  // the manual backend's capture clock

// Runs frames in 1 ms slices, calling the sketch's loop() after each, as the board does.
void run_ms(uint32_t ms) {
  for (uint32_t i = 0; i < ms; ++i) {
    run_frames(25);
    loop();
  }
}

// Delivers `count` captured pulses `width_us` wide to INPUT A, as its capture ISR would. The
// pulses are 10 µs apart on the 16-bit capture counter; dir_high is DIR at the falling edge.
void inject(uint32_t count, uint32_t width_ticks, bool dir_high) {
  static uint32_t rise_ticks = 0;
  for (uint32_t i = 0; i < count; ++i) {
    const CapturedPulse pulse{rise_ticks & 0xFFFFu, (rise_ticks + width_ticks) & 0xFFFFu, dir_high};
    ASSERT_TRUE(inject_pulse(kInputA, pulse));
    rise_ticks += 10 * kTicksPerUs;
  }
}
constexpr uint32_t kXWidthTicks = 2 * kTicksPerUs;  // 300: a 2 µs X pulse
constexpr uint32_t kYWidthTicks = 3 * kTicksPerUs;  // 450: a 3 µs Y pulse

uint32_t wire(const OutputPort& port, uint8_t direction) { return port.pulses_sent(SIGNAL_E, direction); }

class ChainedPlotterDriverTest : public ::testing::Test {
 protected:
  void SetUp() override {
    stepdance::test_support::reset_arduino_board();
    setup();
  }
  void TearDown() override { stepdance::test_support::reset_arduino_board(); }
};

TEST_F(ChainedPlotterDriverTest, ListensOnInputAAndEnablesTheDrivers) {
  EXPECT_STREQ(stepdance::active_board().name, "Driver Module v1.0");
  EXPECT_TRUE(stepdance::engine().running());
  // A Stepdance stream: DIR is read at the STEP falling edge.
  EXPECT_EQ(stepdance::hal_manual::input_edge(kInputA), stepdance::protocol::DirSampleEdge::kFalling);
  EXPECT_FALSE(stepdance::hal_manual::pin_level(14));  // OUTPUT A ENABLE, active low
  EXPECT_FALSE(stepdance::hal_manual::pin_level(13));  // OUTPUT B ENABLE
  EXPECT_FALSE(stepdance::hal_manual::pin_level(39));  // OUTPUT C ENABLE
}

TEST_F(ChainedPlotterDriverTest, XPulsesMoveBothMotorsTheSameWay) {
  // 100 forward X pulses × 0.01 mm: x = +1 mm. CoreXY: a = b = +1 mm = +80 steps at 80 steps/mm.
  // Both channels invert their output, so each port sends 80 pulses with DIR low (reverse).
  inject(100, kXWidthTicks, true);
  run_ms(10);
  EXPECT_EQ(input_a.pulses_received(SIGNAL_X, DIRECTION_FORWARD), 100u);
  EXPECT_DOUBLE_EQ(axidraw_kinematics.input_x.read(ABSOLUTE), 1.0);
  EXPECT_EQ(wire(output_a, DIRECTION_REVERSE), 80u);
  EXPECT_EQ(wire(output_b, DIRECTION_REVERSE), 80u);
  EXPECT_EQ(wire(output_a, DIRECTION_FORWARD) + wire(output_b, DIRECTION_FORWARD), 0u);
}

TEST_F(ChainedPlotterDriverTest, YPulsesMoveTheMotorsOppositeWays) {
  // 50 forward Y pulses: y = +0.5 mm, so a = +40 steps and b = −40 steps; inverted on the wire:
  // A sends 40 reverse, B 40 forward.
  inject(50, kYWidthTicks, true);
  run_ms(10);
  EXPECT_EQ(input_a.pulses_received(SIGNAL_Y, DIRECTION_FORWARD), 50u);
  EXPECT_EQ(wire(output_a, DIRECTION_REVERSE), 40u);
  EXPECT_EQ(wire(output_b, DIRECTION_FORWARD), 40u);
  EXPECT_EQ(wire(output_a, DIRECTION_FORWARD) + wire(output_b, DIRECTION_REVERSE), 0u);
}

TEST_F(ChainedPlotterDriverTest, ReversePulsesOnBothAxesMoveOnlyMotorA) {
  // 30 reverse X and 30 reverse Y: x = y = −0.3 mm. a = −0.6 mm = −48 steps (48 forward on the
  // inverted wire); b = x − y = 0, so motor B stays put.
  inject(30, kXWidthTicks, false);
  inject(30, kYWidthTicks, false);
  run_ms(10);
  EXPECT_EQ(wire(output_a, DIRECTION_FORWARD), 48u);
  EXPECT_EQ(wire(output_a, DIRECTION_REVERSE), 0u);
  EXPECT_EQ(wire(output_b, DIRECTION_FORWARD) + wire(output_b, DIRECTION_REVERSE), 0u);
}

TEST_F(ChainedPlotterDriverTest, WidthsRoundToTheNearestMicrosecondAndGlitchesAreRejected) {
  // 2.4 µs (360 ticks) is still X; a 0.5 µs glitch (75 ticks) is too short and moves nothing.
  inject(10, 360, true);
  inject(1, 75, true);
  run_ms(5);
  EXPECT_EQ(input_a.pulses_received(SIGNAL_X, DIRECTION_FORWARD), 10u);
  EXPECT_EQ(input_a.rejected_too_short(), 1u);
  EXPECT_EQ(wire(output_a, DIRECTION_REVERSE), 8u);  // 0.1 mm = 8 steps
}

TEST_F(ChainedPlotterDriverTest, FramesFromTheKnobsModuleDriveMotorB) {
  // 100 frames as the Basic Module sends them while knob 1 turns +1 count and knob 2 −1 count
  // per frame: X reverse and Y forward in each. Every wire pulse is captured as INPUT A would.
  // x = −1 mm, y = +1 mm: a = x + y = 0, b = x − y = −2 mm = −160 steps, 160 forward on B's wire.
  const auto frame = stepdance::protocol::encode_frame({/*active*/ 0b11, /*forward*/ 0b10, 0});
  stepdance::protocol::WirePulse pulses[16];
  const size_t count = stepdance::protocol::read_wire_pulses(frame.words, pulses, 16);
  ASSERT_EQ(count, 2u);
  const auto clock = stepdance::hal::port_in_clock(kInputA);
  uint32_t frame_start_ticks = 0;
  for (uint32_t i = 0; i < 100; ++i) {
    for (size_t p = 0; p < count; ++p) {
      inject_pulse(kInputA, stepdance::protocol::capture_wire_pulse(pulses[p], clock, frame_start_ticks,
                                                                    stepdance::protocol::DirSampleEdge::kFalling));
    }
    run_frames(1);
    frame_start_ticks = (frame_start_ticks + 40 * kTicksPerUs) & clock.counter_mask;
  }
  run_ms(10);
  EXPECT_EQ(input_a.pulses_received(SIGNAL_X, DIRECTION_REVERSE), 100u);
  EXPECT_EQ(input_a.pulses_received(SIGNAL_Y, DIRECTION_FORWARD), 100u);
  EXPECT_EQ(wire(output_a, DIRECTION_FORWARD) + wire(output_a, DIRECTION_REVERSE), 0u);
  EXPECT_EQ(wire(output_b, DIRECTION_FORWARD), 160u);
  EXPECT_EQ(wire(output_b, DIRECTION_REVERSE), 0u);
}

TEST_F(ChainedPlotterDriverTest, TheScenarioSquareGivesTheCountsItsScenarioExpects) {
  // The moves of examples/ChainedPlotterDriver/scenario.toml, as pulses on INPUT A (a positive
  // knob count arrives as a reverse pulse), one pulse every 2 frames, one axis at a time.
  struct Move {
    uint32_t pulses;
    uint32_t width_ticks;
    bool dir_high;
  };
  const Move moves[] = {
      {1000, kXWidthTicks, false}, {1000, kYWidthTicks, false},  // to (10, 10), pen up
      {2000, kXWidthTicks, false}, {2000, kYWidthTicks, false},  // the square, pen down
      {2000, kXWidthTicks, true},  {2000, kYWidthTicks, true},
  };
  for (const Move& move : moves) {
    for (uint32_t i = 0; i < move.pulses; ++i) {
      inject(1, move.width_ticks, move.dir_high);
      run_frames(2);
    }
    run_ms(5);
  }
  EXPECT_EQ(wire(output_a, DIRECTION_FORWARD), 4800u);
  EXPECT_EQ(wire(output_a, DIRECTION_REVERSE), 3200u);
  EXPECT_EQ(wire(output_b, DIRECTION_FORWARD), 4000u);
  EXPECT_EQ(wire(output_b, DIRECTION_REVERSE), 4000u);
  // The motors count +1 per DIR-high step: A = 1600, B = 0, so the pen is at
  // x = (1600 + 0) / 2 / 80 = 10 mm, y = (1600 − 0) / 2 / 80 = 10 mm.
  EXPECT_DOUBLE_EQ(channel_a.current_position, -1600.0);  // the channel's own, uninverted sense
  EXPECT_DOUBLE_EQ(channel_b.current_position, 0.0);
}

TEST_F(ChainedPlotterDriverTest, ButtonTogglesThePenDownAndUp) {
  // Press: the pen goes to −200 servo steps at 2000 steps/s (0.1 s); the next press lifts it
  // to +200, 400 steps back.
  stepdance::hal_manual::set_pin(kButtonPin, true);
  run_ms(60);
  stepdance::hal_manual::set_pin(kButtonPin, false);
  run_ms(200);
  EXPECT_EQ(wire(output_c, DIRECTION_REVERSE), 200u);
  EXPECT_EQ(wire(output_c, DIRECTION_FORWARD), 0u);
  stepdance::hal_manual::set_pin(kButtonPin, true);
  run_ms(60);
  stepdance::hal_manual::set_pin(kButtonPin, false);
  run_ms(250);
  EXPECT_EQ(wire(output_c, DIRECTION_FORWARD), 400u);
  EXPECT_DOUBLE_EQ(channel_z.current_position, 200.0);
}

}  // namespace
