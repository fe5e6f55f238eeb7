// A one-line progress bar on stderr for long simulations (only drawn on a terminal).
#pragma once

#include <chrono>

#include "common/sim_time.hpp"

namespace stepdance::cli {

/// Redraws `[#####.....]  42%  12.6 / 30.0 s simulated` in place on stderr, at most ten times a
/// second of wall time. Disabled (draws nothing) unless asked for and stderr is a terminal.
class ProgressBar {
 public:
  explicit ProgressBar(bool wanted);
  /// Shows `done` of `total` simulated ns.
  void update(sim::SimTime done, sim::SimTime total);
  /// Erases the bar (before printing other lines; the next update draws it again).
  void clear();
  bool active() const { return enabled_; }

 private:
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point last_draw_{};
};

}  // namespace stepdance::cli
