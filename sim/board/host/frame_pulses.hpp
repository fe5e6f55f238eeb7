// Counting the STEP pulses of a played frame as a Stepdance receiver would decode them.
#pragma once

#include <cstdint>

#include "output/pulse_counts.hpp"
#include "stepdance/protocol/pulse_decoder.hpp"

namespace stepdance::sim {

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
      DirectionCounts& signal = counts[static_cast<uint8_t>(width - protocol::kMinPulseWidthUs)];
      ++(forward ? signal.forward : signal.reverse);
    }
  }
}

}  // namespace stepdance::sim
