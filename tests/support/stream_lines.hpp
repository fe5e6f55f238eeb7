// Test helper: a STEP/DIR stream rebuilt from frame words one microsecond at a time, and decoded
// pulse by pulse with the protocol's decoder, as an input port would count it.
#pragma once

#include <gtest/gtest.h>

#include <stdint.h>

#include <algorithm>
#include <vector>

#include "stepdance/protocol/pulse_decoder.hpp"
#include "stepdance/protocol/signals.hpp"

namespace stepdance::test_support {

inline constexpr protocol::CaptureClock kClock{150, 0xFFFFu};  // the Teensy's 150 MHz capture counter

// The two lines, one level per microsecond of the whole stream, built here from the frame words
// alone: frame k's bit n is the level at k × period + n µs.
struct Lines {
  std::vector<bool> step;
  std::vector<bool> dir;
};

// Appends one frame. Every bit from the period on must be low (else frames would overlap).
inline void append_frame(Lines& lines, const protocol::FrameWords& words, uint32_t period_us) {
  for (uint32_t bit = 0; bit < 32; ++bit) {
    const bool step = (words.step_bits >> bit) & 1u;
    const bool dir = (words.dir_bits >> bit) & 1u;
    if (bit >= period_us) {
      ASSERT_FALSE(step || dir) << "bit " << bit << " of a " << period_us << " µs frame";
      continue;
    }
    lines.step.push_back(step);
    lines.dir.push_back(dir);
  }
  for (uint32_t bit = 32; bit < period_us; ++bit) {
    lines.step.push_back(false);
    lines.dir.push_back(false);
  }
}

// Net steps per signal decoded from the lines, as an input port in `mode` counts them (DIR
// sampled at the edge the mode names); in STEP_DIR mode every pulse is signal X.
struct Decoded {
  int32_t net[kNumSignals] = {};
  uint32_t rejected = 0;
  uint32_t shortest_gap_us = UINT32_MAX;
};

inline Decoded decode(const Lines& lines, InputMode mode) {
  Decoded out;
  size_t t = 0;
  size_t last_fall = 0;
  bool any = false;
  while (t < lines.step.size()) {
    if (!lines.step[t]) {
      ++t;
      continue;
    }
    const size_t rise = t;
    while (t < lines.step.size() && lines.step[t]) ++t;
    const size_t fall = t;
    if (any) out.shortest_gap_us = std::min<uint32_t>(out.shortest_gap_us, static_cast<uint32_t>(rise - last_fall));
    any = true;
    last_fall = fall;
    // DIR at an edge: the level of the microsecond that starts there.
    const bool dir =
        protocol::dir_sample_edge(mode) == protocol::DirSampleEdge::kRising ? lines.dir[rise] : lines.dir[fall];
    const protocol::CapturedPulse pulse = protocol::captured_from_ticks(rise * 150, fall * 150, dir, kClock);
    const protocol::DecodedPulse decoded = protocol::decode_pulse(pulse, kClock, mode, SIGNAL_X);
    if (decoded.verdict != protocol::PulseVerdict::kAccepted) {
      ++out.rejected;
      continue;
    }
    out.net[decoded.signal] += decoded.direction;
  }
  return out;
}

}  // namespace stepdance::test_support
