// A 100 kHz single-axis stream (X in every 10 µs frame) through the cable model: glitches are
// rejected, and a stretch sweep finds, per frame period and input mode, the stretch range that
// still decodes exactly. The 60-second soak is tests/sim/soak/high_speed_cable_soak.cpp.
#include <gtest/gtest.h>

#include <cstdio>

#include "sim/models/high_speed_stream.hpp"

namespace stepdance::sim {
namespace {

TEST(HighSpeedCable, GlitchesBetween100kHzPulsesAreRejectedAndNoStepIsLost) {
  CableSettings settings;
  settings.stretch = 200;
  settings.glitch_every = 37 * kMicrosecond;                           // drifts across the frame phase
  settings.glitch_width = 500;                                         // rounds to 0 µs: too short for either mode
  const StreamResult r = stream(10, 100000, settings, x_every_frame);  // 1 s
  EXPECT_GT(r.cable.glitches_injected, 10000u);
  EXPECT_EQ(r.stepdance.net[SIGNAL_X], r.expected[SIGNAL_X]);
  EXPECT_EQ(r.stepdance.accepted, 100000u);
  EXPECT_EQ(r.stepdance.rejected, r.cable.glitches_injected);
  EXPECT_EQ(r.step_dir.net[SIGNAL_X], r.expected[SIGNAL_X]);
}

// The busiest stream each period's frame holds, alternating two fills so every pair of
// neighbours meets: 40 µs XYRT then YRTZ … (2 µs gaps inside frames), 20/25 µs XYR/XYT,
// 10 µs one signal per frame, E included (3 µs to the next frame's pulse).
protocol::FrameRequest busiest(uint32_t period_us, uint64_t k) {
  static const uint8_t k40[] = {0b001111, 0b011110, 0b110001, 0b101010};
  static const uint8_t k20[] = {0b000111, 0b001011, 0b100001, 0b010010};
  const uint8_t forward = static_cast<uint8_t>(k % 3 == 0 ? 0x3F : (k % 3 == 1 ? 0x15 : 0x00));
  uint8_t mask = 0;
  if (period_us == 40)
    mask = k40[k % 4];
  else if (period_us >= 20)
    mask = k20[k % 4];
  else
    mask = static_cast<uint8_t>(1u << (k % kNumSignals));
  return protocol::FrameRequest{mask, static_cast<uint8_t>(forward & mask), 0};
}

bool exact(const StreamResult& r, const FarEnd& end, bool summed) {
  if (end.rejected != 0) return false;
  if (summed) {
    int64_t total = 0;
    for (int64_t n : r.expected) total += n;
    return end.net[SIGNAL_X] == total;
  }
  for (uint8_t s = 0; s < kNumSignals; ++s) {
    if (end.net[s] != r.expected[s]) return false;
  }
  return true;
}

// Sweeps the stretch in 50 ns steps (up to ±4 µs) and finds the first failing stretch on each
// side. Width-coded (STEPDANCE) decoding rounds to the nearest µs with ties down, so it fails at
// −0.5 µs (X becomes 1.5 µs → 1 µs) and at +0.55 µs (X 2.55 µs → 3 µs, a Y) at every period.
// STEP_DIR decoding counts any pulse longer than 0.5 µs and reads DIR at the rising edge, so it
// fails when X shrinks to 0.5 µs (−1.5 µs) or a pulse is stretched onto the next one of the same
// frame, 2 µs away (+2 µs). At 10 µs a frame holds one signal and the next pulse is in the next
// frame (≥ 3 µs away); the cable model never merges across frames (it moves the next rise 1 ns
// past a late fall, see models/cable.hpp), so no positive stretch up to 4 µs fails there.
TEST(HighSpeedCable, StretchToleranceAtEveryPeriod) {
  constexpr SimTime kNone = 0;  // no failure within the sweep
  struct Expected {
    uint32_t period_us;
    SimTime stepdance_low, stepdance_high, step_dir_low, step_dir_high;  // first failing stretch (ns)
  };
  const Expected table[] = {
      {40, -500, 550, -1500, 2000},
      {25, -500, 550, -1500, 2000},
      {20, -500, 550, -1500, 2000},
      {10, -500, 550, -1500, kNone},
  };
  for (const Expected& row : table) {
    SimTime found[4] = {0, 0, 0, 0};
    for (int side = 0; side < 2; ++side) {
      bool stepdance_ok = true;
      bool step_dir_ok = true;
      for (SimTime s = 0; (stepdance_ok || step_dir_ok) && s <= 4000; s += 50) {
        CableSettings settings;
        settings.stretch = side == 0 ? -s : s;
        const StreamResult r =
            stream(row.period_us, 2000, settings, [&](uint64_t k) { return busiest(row.period_us, k); });
        if (stepdance_ok && !exact(r, r.stepdance, false)) {
          stepdance_ok = false;
          found[side] = settings.stretch;
        }
        if (step_dir_ok && !exact(r, r.step_dir, true)) {
          step_dir_ok = false;
          found[2 + side] = settings.stretch;
        }
      }
    }
    std::printf(
        "period %2u us: first failing stretch: STEPDANCE %+5lld / %+5lld ns, STEP_DIR %+5lld / %+5lld ns (0: none "
        "within 4 us)\n",
        row.period_us, static_cast<long long>(found[0]), static_cast<long long>(found[1]),
        static_cast<long long>(found[2]), static_cast<long long>(found[3]));
    EXPECT_EQ(found[0], row.stepdance_low) << row.period_us;
    EXPECT_EQ(found[1], row.stepdance_high) << row.period_us;
    EXPECT_EQ(found[2], row.step_dir_low) << row.period_us;
    EXPECT_EQ(found[3], row.step_dir_high) << row.period_us;
  }
}

}  // namespace
}  // namespace stepdance::sim
