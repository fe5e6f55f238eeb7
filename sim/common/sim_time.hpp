// Simulated time: signed 64-bit nanoseconds since the start of a simulation.
#pragma once

#include <cstdint>

namespace stepdance::sim {

/// Nanoseconds of simulated time since the simulation started.
using SimTime = int64_t;

constexpr SimTime kNanosecond = 1;
constexpr SimTime kMicrosecond = 1000;
constexpr SimTime kMillisecond = 1000 * kMicrosecond;
constexpr SimTime kSecond = 1000 * kMillisecond;

/// Seconds (as written in scenario files) to simulated time, rounded to the nearest ns.
constexpr SimTime from_seconds(double seconds) {
  return static_cast<SimTime>(seconds * 1e9 + (seconds >= 0 ? 0.5 : -0.5));
}
/// Simulated time to seconds.
constexpr double to_seconds(SimTime time) { return static_cast<double>(time) / 1e9; }

}  // namespace stepdance::sim
