// Compiles examples/ChainedKnobsBasic/ChainedKnobsBasic.ino on the manual backend and checks
// its motion stream: knob counts in, X/Y pulses out of OUTPUT A, readable by a receiver.
// (Its own executable: the sketch defines the global setup() and loop().)
#include <gtest/gtest.h>

#include "../arduino_fixture.hpp"
#include "stepdance/protocol/frame_reader.hpp"
#include "stepdance/protocol/pulse_decoder.hpp"

#include "../../../../examples/ChainedKnobsBasic/ChainedKnobsBasic.ino"

namespace {

using stepdance::hal_manual::frames_written;
using stepdance::hal_manual::last_frame;
using stepdance::hal_manual::run_frames;
using stepdance::hal_manual::set_quadrature;

constexpr uint8_t kPortA = 0;

// Runs frames in 1 ms slices, calling the sketch's loop() after each, as the board does.
void run_ms(uint32_t ms) {
  for (uint32_t i = 0; i < ms; ++i) {
    run_frames(25);
    loop();
  }
}

uint32_t sent(uint8_t signal, uint8_t direction) { return output_a.pulses_sent(signal, direction); }

class ChainedKnobsBasicTest : public ::testing::Test {
 protected:
  void SetUp() override {
    stepdance::test_support::reset_arduino_board();
    setup();
  }
  void TearDown() override { stepdance::test_support::reset_arduino_board(); }
};

TEST_F(ChainedKnobsBasicTest, RunsOnTheBasicModuleWithItsOneOutputPort) {
  EXPECT_STREQ(stepdance::active_board().name, "Basic Module v1.0");
  EXPECT_TRUE(stepdance::engine().running());
  EXPECT_TRUE(stepdance::hal_manual::output_claimed(kPortA));
  EXPECT_FALSE(stepdance::hal_manual::output_claimed(1));
  EXPECT_EQ(stepdance::fault_reason(), stepdance::FaultReason::kNone);
}

TEST_F(ChainedKnobsBasicTest, EachCountOfKnobOneIsOneXPulse) {
  // +100 counts on the inverted knob: x = −100 × 0.01 mm = −1 mm = −100 pulses of 0.01 mm.
  // The channel emits at most one pulse per frame, so 10 ms (250 frames) is plenty.
  set_quadrature(0, 100);
  run_ms(10);
  EXPECT_EQ(sent(SIGNAL_X, DIRECTION_REVERSE), 100u);
  EXPECT_EQ(sent(SIGNAL_X, DIRECTION_FORWARD), 0u);
  EXPECT_EQ(sent(SIGNAL_Y, DIRECTION_FORWARD) + sent(SIGNAL_Y, DIRECTION_REVERSE), 0u);
  EXPECT_DOUBLE_EQ(channel_x.current_position, -100.0);
}

TEST_F(ChainedKnobsBasicTest, KnobTwoDrivesYOnly) {
  // −40 counts on the inverted knob 2: y = +0.4 mm = 40 forward Y pulses.
  set_quadrature(1, -40);
  run_ms(5);
  EXPECT_EQ(sent(SIGNAL_Y, DIRECTION_FORWARD), 40u);
  EXPECT_EQ(sent(SIGNAL_Y, DIRECTION_REVERSE), 0u);
  EXPECT_EQ(sent(SIGNAL_X, DIRECTION_FORWARD) + sent(SIGNAL_X, DIRECTION_REVERSE), 0u);
}

TEST_F(ChainedKnobsBasicTest, TheScenarioKnobTurnsGiveItsExpectedCounts) {
  // The turns of examples/ChainedPlotterDriver/scenario.toml, one count every 0.5 ms:
  // knob_x +1000, knob_y +1000, knob_x +2000, knob_y +2000, knob_x −2000, knob_y −2000.
  const struct {
    uint8_t knob;
    int32_t counts;
  } turns[] = {{0, 1000}, {1, 1000}, {0, 2000}, {1, 2000}, {0, -2000}, {1, -2000}};
  int32_t count[2] = {0, 0};
  for (const auto& turn : turns) {
    const int32_t step = turn.counts > 0 ? 1 : -1;
    for (int32_t i = 0; i != turn.counts; i += step) {
      count[turn.knob] += step;
      set_quadrature(turn.knob, count[turn.knob]);
      run_frames(12);
      if (i % 50 == 0) loop();
    }
    run_ms(5);
  }
  EXPECT_EQ(sent(SIGNAL_X, DIRECTION_FORWARD), 2000u);
  EXPECT_EQ(sent(SIGNAL_X, DIRECTION_REVERSE), 3000u);
  EXPECT_EQ(sent(SIGNAL_Y, DIRECTION_FORWARD), 2000u);
  EXPECT_EQ(sent(SIGNAL_Y, DIRECTION_REVERSE), 3000u);
}

TEST_F(ChainedKnobsBasicTest, OneCountIsOneTwoMicrosecondPulseInTheNextFrame) {
  set_quadrature(0, 1);
  run_frames(1);
  // X (2 µs) is the frame's first pulse: STEP high from 2 to 4 µs; reverse, so DIR stays low.
  EXPECT_EQ(frames_written(kPortA), 1u);
  EXPECT_EQ(last_frame(kPortA).step_bits, 0x0000000Cu);
  EXPECT_EQ(last_frame(kPortA).dir_bits, 0u);
  run_frames(1);
  EXPECT_EQ(last_frame(kPortA).step_bits, 0u);  // nothing more to send
}

TEST_F(ChainedKnobsBasicTest, BothKnobsShareAFrame) {
  // X reverse at 2–4 µs; after a 2 µs gap, Y forward (3 µs) at 6–9 µs, with DIR high from
  // 1 µs before its rise to 1 µs after its fall (5–10 µs).
  set_quadrature(0, 1);
  set_quadrature(1, -1);
  run_frames(1);
  EXPECT_EQ(last_frame(kPortA).step_bits, 0x0000000Cu | 0x000001C0u);
  EXPECT_EQ(last_frame(kPortA).dir_bits, 0x000003E0u);
}

TEST_F(ChainedKnobsBasicTest, AReceiverDecodesExactlyWhatWasSent) {
  // Turn both knobs, then read every frame back off the wire as an input port would: each STEP
  // pulse captured with a 150 MHz clock, DIR at the falling edge, decoded by width.
  // ENC1 +250 → 250 reverse X; ENC2 −120 → 120 forward Y. 300 frames cover the longer run.
  set_quadrature(0, 250);
  set_quadrature(1, -120);
  const stepdance::protocol::CaptureClock clock{150, 0xFFFFu};
  uint32_t decoded[NUM_SIGNALS][2] = {};
  uint32_t rejected = 0;
  uint32_t frame_start_ticks = 0;
  for (uint32_t frame = 0; frame < 300; ++frame) {
    run_frames(1);
    if (frame % 25 == 24) loop();
    stepdance::protocol::WirePulse pulses[16];
    const size_t count = stepdance::protocol::read_wire_pulses(last_frame(kPortA), pulses, 16);
    for (size_t i = 0; i < count; ++i) {
      const auto captured = stepdance::protocol::capture_wire_pulse(pulses[i], clock, frame_start_ticks,
                                                                    stepdance::protocol::DirSampleEdge::kFalling);
      const auto pulse = stepdance::protocol::decode_pulse(captured, clock, INPUT_MODE_STEPDANCE, SIGNAL_X);
      if (pulse.verdict != stepdance::protocol::PulseVerdict::kAccepted) {
        ++rejected;
        continue;
      }
      ++decoded[pulse.signal][pulse.direction > 0 ? DIRECTION_FORWARD : DIRECTION_REVERSE];
    }
    frame_start_ticks = (frame_start_ticks + 40 * 150) & clock.counter_mask;
  }
  EXPECT_EQ(rejected, 0u);
  EXPECT_EQ(decoded[SIGNAL_X][DIRECTION_REVERSE], 250u);
  EXPECT_EQ(decoded[SIGNAL_Y][DIRECTION_FORWARD], 120u);
  for (uint8_t signal = 0; signal < NUM_SIGNALS; ++signal) {
    for (uint8_t direction : {DIRECTION_REVERSE, DIRECTION_FORWARD}) {
      EXPECT_EQ(decoded[signal][direction], sent(signal, direction))
          << "signal " << int{signal} << " direction " << int{direction};
    }
  }
  EXPECT_EQ(output_a.signals_carried(), 0u);  // X + Y always fit in one frame
}

}  // namespace
