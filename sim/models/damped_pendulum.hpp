// A damped pendulum whose pivot turns an encoder shaft: the harmonograph's input device.
#pragma once

#include <cstdint>

#include "common/sim_time.hpp"

namespace stepdance::sim {

/// How the pendulum is built and released.
struct PendulumSettings {
  /// Encoder pulses per revolution per channel (×4 = counts per revolution).
  int32_t pulses_per_revolution = 600;
  /// Angle from vertical it is held at until released (degrees, > 0).
  double amplitude_deg = 30;
  /// Period of one full swing (s) and time constant of the amplitude's decay (s).
  double period_s = 2;
  double decay_s = 30;
  /// When it is let go (ns from the start of the run).
  SimTime release = 0;
};

/// θ(t) = A (held) before the release at t₀, then θ(t) = A·e^{−(t−t₀)/τ}·cos(2π(t−t₀)/T): a
/// lightly damped pendulum let go from rest. Its encoder has edges every 1/counts_per_revolution
/// of a turn; the counter holds the number of edges crossed since time 0, i.e.
/// floor(θ(t)·cpr/2π) − floor(θ(0)·cpr/2π) — the count is 0 at power-on, where it was held.
class DampedPendulum {
 public:
  explicit DampedPendulum(const PendulumSettings& settings);

  /// Angle from vertical at `time` (radians).
  double angle_rad_at(SimTime time) const;
  /// Encoder counter value at `time`.
  int64_t count_at(SimTime time) const;
  /// Counts per revolution (4 × pulses per revolution).
  int64_t counts_per_revolution() const { return int64_t{4} * settings_.pulses_per_revolution; }
  const PendulumSettings& settings() const { return settings_; }

 private:
  int64_t edges_below(double angle_rad) const;

  PendulumSettings settings_;
  int64_t edges_at_start_;
};

}  // namespace stepdance::sim
