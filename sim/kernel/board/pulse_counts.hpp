// Per-port tallies of STEP pulses by signal and direction, and of pulses a decoder rejected.
#pragma once

#include <cstdint>

#include "stepdance/protocol/pulse_decoder.hpp"
#include "stepdance/protocol/signals.hpp"

namespace stepdance::sim {

/// Pulses seen on one port. Signals are indexed SIGNAL_X..SIGNAL_E.
struct PulseCounts {
  uint64_t forward[kNumSignals] = {};
  uint64_t reverse[kNumSignals] = {};
  uint64_t too_short = 0;  ///< rejected: narrower than the mode accepts (glitches)
  uint64_t too_long = 0;   ///< rejected: wider than the widest signal

  /// Adds one decoded pulse.
  void add(const protocol::DecodedPulse& pulse) {
    switch (pulse.verdict) {
      case protocol::PulseVerdict::kAccepted:
        ++(pulse.direction > 0 ? forward : reverse)[pulse.signal];
        break;
      case protocol::PulseVerdict::kTooShort: ++too_short; break;
      case protocol::PulseVerdict::kTooLong: ++too_long; break;
    }
  }
  /// Accepted pulses over all signals and both directions.
  uint64_t accepted() const {
    uint64_t total = 0;
    for (uint8_t signal = 0; signal < kNumSignals; ++signal) total += forward[signal] + reverse[signal];
    return total;
  }
  /// Rejected pulses for any reason.
  uint64_t rejected() const { return too_short + too_long; }
};

/// Decodes every STEP pulse of a played frame as a Stepdance receiver would (width → signal,
/// DIR at the falling edge) and adds it to `counts`. Pulses that fall more than
/// `last_fall_us` µs after the frame start are left out (they end after the run does).
///
/// Widths on the wire are whole microseconds, so this is decode_pulse() without the capture
/// arithmetic: w µs → signal w − 2 for 2..7, too short below, too long above. A pulse still
/// high at bit 31 ends at 32 µs, where DIR is low.
inline void count_frame_pulses(const protocol::FrameWords& words, PulseCounts& counts,
                               int64_t last_fall_us = protocol::kFrameBitsUs) {
  const uint64_t step = words.step_bits;
  uint64_t rises = step & ~(step << 1);
  while (rises != 0) {
    const int rise = __builtin_ctzll(rises);
    rises &= rises - 1;
    const int fall = __builtin_ctzll(~(step >> rise)) + rise;  // first low bit after the rise
    if (fall > last_fall_us) continue;
    const int width = fall - rise;
    if (width < protocol::kMinPulseWidthUs) {
      ++counts.too_short;
    } else if (width > protocol::kMaxPulseWidthUs) {
      ++counts.too_long;
    } else {
      const bool forward = ((uint64_t{words.dir_bits} >> fall) & 1u) != 0;
      ++(forward ? counts.forward : counts.reverse)[width - protocol::kMinPulseWidthUs];
    }
  }
}

}  // namespace stepdance::sim
