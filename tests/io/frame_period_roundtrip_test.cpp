// At every supported frame period, all 63 signal sets go out through an OutputPort (fitting or
// carried over) and come back exactly through the pulse decoder, in both input modes.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "hal_manual.hpp"
#include "stepdance/core/frame_period.hpp"
#include "stepdance/io/output_port.hpp"
#include "stepdance/protocol/pulse_decoder.hpp"
#include "support/engine_fixture.hpp"
#include "support/stream_lines.hpp"

namespace stepdance {
namespace {

using test_support::append_frame;
using test_support::decode;
using test_support::Decoded;
using test_support::Lines;

constexpr uint32_t kPeriodsUs[] = {10, 20, 25, 40};
constexpr uint32_t kPulsesPerSignal = 3;
class FramePeriodRoundTripTest : public test_support::EngineFixture {};

TEST_F(FramePeriodRoundTripTest, All63SignalSetsComeBackExactlyAtEveryPeriodInBothInputModes) {
  const uint8_t direction_patterns[] = {0x00, 0x3F, 0x15, 0x2A};  // all reverse, all forward, mixed
  for (const uint32_t period_us : kPeriodsUs) {
    for (uint8_t mask = 1; mask <= kAllSignalsMask; ++mask) {
      for (const uint8_t forward : direction_patterns) {
        test_support::reset_global_state();
        ASSERT_EQ(set_frame_period_us(period_us), Status::kOk);
        OutputPort port;  // the whole frame of the period: OUTPUT_FRAME_32US at 40 µs
        ASSERT_EQ(port.begin(OUTPUT_A), Status::kOk);
        int32_t expected[kNumSignals] = {};
        int32_t expected_total = 0;
        for (uint8_t signal = 0; signal < kNumSignals; ++signal) {
          if (!(mask & (1u << signal))) continue;
          const bool fwd = forward & (1u << signal);
          for (uint32_t n = 0; n < kPulsesPerSignal; ++n)
            port.add_signal(signal, fwd ? DIRECTION_FORWARD : DIRECTION_REVERSE);
          expected[signal] = fwd ? int32_t{kPulsesPerSignal} : -int32_t{kPulsesPerSignal};
          expected_total += expected[signal];
        }
        // At most one pulse per signal per frame, and at least one signal per frame: 18 frames
        // send everything; two idle frames close the stream.
        Lines lines;
        for (int frame = 0; frame < 20; ++frame) {
          port.transmit_frame();
          append_frame(lines, hal_manual::last_frame(OUTPUT_A), period_us);
        }
        for (uint8_t signal = 0; signal < kNumSignals; ++signal) ASSERT_EQ(port.pending(signal), 0);
        const Decoded stepdance = decode(lines, INPUT_MODE_STEPDANCE);
        const Decoded step_dir = decode(lines, INPUT_MODE_STEP_DIR);
        const std::string where =
            std::to_string(period_us) + " µs, set " + std::to_string(mask) + ", forward " + std::to_string(forward);
        for (uint8_t signal = 0; signal < kNumSignals; ++signal) {
          EXPECT_EQ(stepdance.net[signal], expected[signal]) << where << ", signal " << int(signal);
        }
        EXPECT_EQ(step_dir.net[SIGNAL_X], expected_total) << where;
        EXPECT_EQ(stepdance.rejected + step_dir.rejected, 0u) << where;
        EXPECT_GE(stepdance.shortest_gap_us, 2u) << where;
      }
    }
  }
}

}  // namespace
}  // namespace stepdance
