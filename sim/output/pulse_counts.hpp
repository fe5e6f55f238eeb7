// Pulse counts per axis-coded signal and direction, and the rejected ones: the one tally of the
// simulated boards' ports, the capture decoder and the run summary.
#pragma once

#include <array>
#include <cstdint>

#include <nlohmann/json.hpp>

#include "stepdance/protocol/pulse_decoder.hpp"
#include "stepdance/protocol/signals.hpp"

namespace stepdance::sim {

/// Pulses of one signal in each direction.
struct DirectionCounts {
  uint64_t forward = 0;  ///< DIR high
  uint64_t reverse = 0;  ///< DIR low

  bool operator==(const DirectionCounts& other) const { return forward == other.forward && reverse == other.reverse; }
  bool operator!=(const DirectionCounts& other) const { return !(*this == other); }
};

/// Pulses seen on one port or one STEP/DIR pair: the accepted ones per signal (indexed by
/// stepdance::Signal: X, Y, R, T, Z, E) and direction, the rejected ones by reason.
struct PulseCounts {
  std::array<DirectionCounts, kNumSignals> signals{};
  uint64_t too_short = 0;  ///< rejected: narrower than the mode accepts (glitches)
  uint64_t too_long = 0;   ///< rejected: wider than the widest signal

  DirectionCounts& operator[](uint8_t signal) { return signals[signal]; }
  const DirectionCounts& operator[](uint8_t signal) const { return signals[signal]; }

  /// Adds one decoded pulse.
  void add(const protocol::DecodedPulse& pulse) {
    switch (pulse.verdict) {
      case protocol::PulseVerdict::kAccepted: {
        DirectionCounts& counts = signals[pulse.signal];
        ++(pulse.direction > 0 ? counts.forward : counts.reverse);
        break;
      }
      case protocol::PulseVerdict::kTooShort: ++too_short; break;
      case protocol::PulseVerdict::kTooLong: ++too_long; break;
    }
  }
  /// Accepted pulses over all signals and both directions.
  uint64_t accepted() const {
    uint64_t total = 0;
    for (const DirectionCounts& counts : signals) total += counts.forward + counts.reverse;
    return total;
  }
  /// Rejected pulses for any reason.
  uint64_t rejected() const { return too_short + too_long; }

  bool operator==(const PulseCounts& other) const {
    return signals == other.signals && too_short == other.too_short && too_long == other.too_long;
  }
  bool operator!=(const PulseCounts& other) const { return !(*this == other); }
};

/// The letter naming a signal: "X", "Y", "R", "T", "Z", "E"; "?" out of range.
inline const char* signal_name(uint8_t signal) {
  static const char* const kNames[kNumSignals] = {"X", "Y", "R", "T", "Z", "E"};
  return signal < kNumSignals ? kNames[signal] : "?";
}

/// {"E": {"forward": n, "reverse": n}, …, "Z": {…}} with all six signals (the accepted pulses).
inline nlohmann::json signal_counts_json(const PulseCounts& counts) {
  nlohmann::json out = nlohmann::json::object();
  for (uint8_t signal = 0; signal < kNumSignals; ++signal) {
    out[signal_name(signal)] = {{"forward", counts[signal].forward}, {"reverse", counts[signal].reverse}};
  }
  return out;
}

}  // namespace stepdance::sim
