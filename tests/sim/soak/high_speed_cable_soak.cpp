// Soak: a 100 kHz single-axis stream (X in every 10 µs frame) crosses a cable that stretches
// every pulse by +0.2 µs, then one that shrinks it by 0.2 µs, for 60 simulated seconds each, and
// loses no step in either input mode. Labelled `integration` (about 10 s; the sanitizer pass
// skips it): ctest --test-dir build -R sim.soak.
#include <gtest/gtest.h>

#include "sim/models/high_speed_stream.hpp"

namespace stepdance::sim {
namespace {

TEST(HighSpeedCable, A100kHzStreamStretchedByPlusMinus200nsLosesNoStepIn60Seconds) {
  constexpr uint64_t kFrames = 6000000;  // 60 s of 10 µs frames
  // Expected net: 3529 whole 1700-frame cycles (+300 each); the last 700 frames are all forward.
  constexpr int64_t kExpectedNet = 3529 * 300 + 700;
  for (const SimTime stretch : {SimTime{200}, SimTime{-200}}) {
    CableSettings settings;
    settings.stretch = stretch;
    settings.delay = 35;
    const StreamResult r = stream(10, kFrames, settings, x_every_frame);
    EXPECT_EQ(r.expected[SIGNAL_X], kExpectedNet);
    EXPECT_EQ(r.stepdance.net[SIGNAL_X], kExpectedNet) << "stretch " << stretch << " ns";
    EXPECT_EQ(r.stepdance.accepted, kFrames);
    EXPECT_EQ(r.stepdance.rejected, 0u);
    EXPECT_EQ(r.step_dir.net[SIGNAL_X], kExpectedNet);
    EXPECT_EQ(r.cable.pulses_passed, kFrames);
  }
}

}  // namespace
}  // namespace stepdance::sim
