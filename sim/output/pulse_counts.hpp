// Pulse counts per axis-coded signal and direction, shared by the decoder and the run summary.
#pragma once

#include <array>
#include <cstdint>

#include <nlohmann/json.hpp>

#include "stepdance/protocol/signals.hpp"

namespace stepdance::sim {

/// Pulses of one signal in each direction.
struct DirectionCounts {
  uint64_t forward = 0;  ///< DIR high
  uint64_t reverse = 0;  ///< DIR low

  bool operator==(const DirectionCounts& other) const {
    return forward == other.forward && reverse == other.reverse;
  }
  bool operator!=(const DirectionCounts& other) const { return !(*this == other); }
};

/// Counts of every signal, indexed by stepdance::Signal (X, Y, R, T, Z, E).
using SignalCounts = std::array<DirectionCounts, kNumSignals>;

/// The letter naming a signal: "X", "Y", "R", "T", "Z", "E"; "?" out of range.
inline const char* signal_name(uint8_t signal) {
  static const char* const kNames[kNumSignals] = {"X", "Y", "R", "T", "Z", "E"};
  return signal < kNumSignals ? kNames[signal] : "?";
}

/// {"E": {"forward": n, "reverse": n}, …, "Z": {…}} with all six signals.
inline nlohmann::json signal_counts_json(const SignalCounts& counts) {
  nlohmann::json out = nlohmann::json::object();
  for (uint8_t signal = 0; signal < kNumSignals; ++signal) {
    out[signal_name(signal)] = {{"forward", counts[signal].forward}, {"reverse", counts[signal].reverse}};
  }
  return out;
}

}  // namespace stepdance::sim
