// LivePacer: wall-clock deadlines for simulated instants, with a bounded catch-up.
#include "live_pacer.hpp"

#include <cmath>

namespace stepdance::cli {

void LivePacer::anchor(Clock::time_point wall, sim::SimTime simulated, double speed) {
  wall_ = wall;
  simulated_ = simulated;
  speed_ = speed;
}

LivePacer::Due LivePacer::due(sim::SimTime now, Clock::time_point wall) {
  const std::chrono::nanoseconds after_anchor(std::llround(static_cast<double>(now - simulated_) / speed_));
  Due result;
  result.wall = wall_ + std::chrono::duration_cast<Clock::duration>(after_anchor);
  const Clock::duration late = wall - result.wall;
  if (late <= Clock::duration::zero()) return result;
  result.lag_ms = std::chrono::duration<double, std::milli>(late).count();
  if (late <= kCatchUpLimit) return result;
  // Too late to catch up without outrunning whoever waits on the terminals: give the rest up.
  const Clock::duration given_up = late - kCatchUpLimit;
  result.given_up_ms = std::chrono::duration<double, std::milli>(given_up).count();
  wall_ += given_up;
  result.wall += given_up;
  return result;
}

}  // namespace stepdance::cli
