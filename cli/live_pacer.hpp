// LivePacer: when each simulated instant of a live run is due on the wall clock.
#pragma once

#include <chrono>

#include "common/sim_time.hpp"

namespace stepdance::cli {

/// Ties simulated time to the wall clock at a speed (simulated seconds per wall second). A run
/// that falls behind the clock (the machine was busy: other processes, a slow pass) catches up
/// only by kCatchUpLimit; the rest of the lag is given up and the run goes on from where it is,
/// slower than the clock, never faster than `speed`. So a client on the other end of a terminal
/// (a G-code sender, which was slowed down by the same load) is never outrun: the planner never
/// drains in a burst of simulated time the client had no wall time to refill.
/// Context: the live run's thread.
class LivePacer {
 public:
  using Clock = std::chrono::steady_clock;
  /// The most wall time a late run makes up by running faster than `speed`.
  static constexpr std::chrono::microseconds kCatchUpLimit{2000};

  /// Simulated time `simulated` is due at wall time `wall`, and the run goes at `speed` (> 0).
  void anchor(Clock::time_point wall, sim::SimTime simulated, double speed);
  double speed() const { return speed_; }

  /// What a paced instant found: when it is due, and how late the run was (ms of wall time).
  struct Due {
    Clock::time_point wall;
    double lag_ms = 0;       ///< how far past its due time the instant was reached (≥ 0)
    double given_up_ms = 0;  ///< the part of that lag the run gives up (not made up later)
  };
  /// Simulated instant `now`, reached at wall time `wall`: when it is due (the run sleeps until
  /// then). Later than kCatchUpLimit: the anchor moves so `now` is due at wall − kCatchUpLimit.
  Due due(sim::SimTime now, Clock::time_point wall);

 private:
  Clock::time_point wall_{};
  sim::SimTime simulated_ = 0;
  double speed_ = 1.0;
};

}  // namespace stepdance::cli
