// Per-port tallies of STEP pulses by signal and direction, and of pulses a decoder rejected.
#pragma once

#include <cstdint>

#include "stepdance/protocol/frame_reader.hpp"
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
inline void count_frame_pulses(const protocol::FrameWords& words, PulseCounts& counts,
                               int64_t last_fall_us = protocol::kFrameBitsUs) {
  protocol::WirePulse pulses[16];
  const size_t found = protocol::read_wire_pulses(words, pulses, 16);
  const protocol::CaptureClock clock{};
  for (size_t i = 0; i < found; ++i) {
    if (pulses[i].fall_us > last_fall_us) continue;
    const protocol::CapturedPulse captured =
        protocol::capture_wire_pulse(pulses[i], clock, 0, protocol::DirSampleEdge::kFalling);
    counts.add(protocol::decode_pulse(captured, clock, INPUT_MODE_STEPDANCE, SIGNAL_X));
  }
}

}  // namespace stepdance::sim
