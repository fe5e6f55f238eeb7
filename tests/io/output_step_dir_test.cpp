// OUTPUT_MODE_STEP_DIR: one signal as plain 2 µs step pulses, several per frame, DIR held over them.
#include <gtest/gtest.h>

#include "hal_manual.hpp"
#include "stepdance/core/fault.hpp"
#include "stepdance/core/frame_period.hpp"
#include "stepdance/io/output_port.hpp"
#include "support/engine_fixture.hpp"
#include "support/stream_lines.hpp"

namespace stepdance {
namespace {

constexpr uint32_t bits(uint8_t first, uint8_t count) { return ((1u << count) - 1u) << first; }

class OutputStepDirTest : public test_support::EngineFixture {};

TEST_F(OutputStepDirTest, SevenPulsesFitA40MicrosecondFrameAndTheRestFollow) {
  OutputPort a;
  ASSERT_EQ(a.begin(OUTPUT_A, OUTPUT_FRAME_32US, OUTPUT_TRANSMIT_MANUAL), Status::kOk);
  ASSERT_EQ(a.set_output_mode(OUTPUT_MODE_STEP_DIR, SIGNAL_Z), Status::kOk);
  for (int i = 0; i < 9; ++i) a.add_signal(SIGNAL_Z, DIRECTION_FORWARD);
  a.transmit_frame();
  // Pulses rise at 2, 6, … 26 µs (2 µs high, 2 µs low); the last falls at 28 µs, before bit 31.
  uint32_t step = 0;
  for (uint8_t k = 0; k < 7; ++k) step |= bits(static_cast<uint8_t>(2 + 4 * k), 2);
  EXPECT_EQ(hal_manual::last_frame(OUTPUT_A).step_bits, step);
  EXPECT_EQ(hal_manual::last_frame(OUTPUT_A).dir_bits, bits(1, 28));  // 1 µs before the first, after the last
  EXPECT_EQ(a.pending(SIGNAL_Z), 2);
  a.transmit_frame();
  EXPECT_EQ(hal_manual::last_frame(OUTPUT_A).step_bits, bits(2, 2) | bits(6, 2));
  EXPECT_EQ(a.pulses_sent(SIGNAL_Z, DIRECTION_FORWARD), 9u);
}

TEST_F(OutputStepDirTest, ReversePulsesKeepDirLowAndOtherSignalsAreRefused) {
  OutputPort a;
  ASSERT_EQ(a.begin(OUTPUT_A, OUTPUT_FRAME_32US, OUTPUT_TRANSMIT_MANUAL), Status::kOk);
  ASSERT_EQ(a.set_output_mode(OUTPUT_MODE_STEP_DIR), Status::kOk);  // signal X by default
  a.add_signal(SIGNAL_X, DIRECTION_REVERSE);
  a.add_signal(SIGNAL_Y, DIRECTION_FORWARD);
  EXPECT_EQ(a.pulses_refused(), 1u);
  EXPECT_EQ(a.pending(SIGNAL_Y), 0);
  EXPECT_EQ(fault_level(), static_cast<uint8_t>(FaultLevel::kWarning));
  a.transmit_frame();
  EXPECT_EQ(hal_manual::last_frame(OUTPUT_A).step_bits, bits(2, 2));
  EXPECT_EQ(hal_manual::last_frame(OUTPUT_A).dir_bits, 0u);
  EXPECT_EQ(a.set_output_mode(static_cast<OutputMode>(7)), Status::kBadArgument);
  EXPECT_EQ(a.set_output_mode(OUTPUT_MODE_STEP_DIR, 6), Status::kBadArgument);
}

// A step/dir stream at 10 µs frames: two pulses per frame fit (1..3 and 5..7 µs), so a burst of
// pulses drains at 200 000 steps/s; a STEP_DIR input counts every one, with its direction.
TEST_F(OutputStepDirTest, ABurstDrainsTwoPulsesPerTenMicrosecondFrameAndDecodesExactly) {
  ASSERT_EQ(set_frame_period_us(10), Status::kOk);
  OutputPort a;
  ASSERT_EQ(a.begin(OUTPUT_A), Status::kOk);
  a.transmit_frame();  // (engine stopped: the sketch transmits by hand here)
  ASSERT_EQ(a.set_output_mode(OUTPUT_MODE_STEP_DIR), Status::kOk);
  for (int i = 0; i < 101; ++i) a.add_signal(SIGNAL_X, DIRECTION_FORWARD);
  test_support::Lines lines;
  for (int frame = 0; frame < 51; ++frame) {
    a.transmit_frame();
    test_support::append_frame(lines, hal_manual::last_frame(OUTPUT_A), 10);
  }
  EXPECT_EQ(a.pending(SIGNAL_X), 0);
  for (int i = 0; i < 40; ++i) a.add_signal(SIGNAL_X, DIRECTION_REVERSE);
  for (int frame = 0; frame < 21; ++frame) {
    a.transmit_frame();
    test_support::append_frame(lines, hal_manual::last_frame(OUTPUT_A), 10);
  }
  const test_support::Decoded step_dir = test_support::decode(lines, INPUT_MODE_STEP_DIR);
  EXPECT_EQ(step_dir.net[SIGNAL_X], 101 - 40);
  EXPECT_EQ(step_dir.rejected, 0u);
  EXPECT_EQ(step_dir.shortest_gap_us, 2u);
  const test_support::Decoded stepdance = test_support::decode(lines, INPUT_MODE_STEPDANCE);
  EXPECT_EQ(stepdance.net[SIGNAL_X], 101 - 40);  // 2 µs pulses are X to a Stepdance input too
}

}  // namespace
}  // namespace stepdance
