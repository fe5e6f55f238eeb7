// EBB tick clock: ticks of 40 µs (ebb-protocol.md: the EBB's 25 kHz motion interrupt) out of frames.
#include "stepdance/interfaces/ebb/ebb_tick_clock.hpp"

#include <math.h>

#include "stepdance/interfaces/ebb/ebb_motion.hpp"

namespace stepdance::ebb {

// Frame time accumulates in Q16 so a stretched tick (40 µs × a non-integer factor) still falls on
// the right frame, with no drift over a long move.
bool EbbTickClock::advance(uint32_t period_us) {
  time_q16_ += period_us * kUnstretchedQ16;
  const uint32_t tick_q16 = kTickPeriodUs * stretch_q16_;
  if (time_q16_ < tick_q16) return false;
  time_q16_ -= tick_q16;
  return true;
}

double EbbTickClock::carried_per_tick(uint32_t period_us) { return static_cast<double>(kTickPeriodUs) / period_us; }

// A channel steps at most once per frame: a faster move runs on a slower clock, the whole move, so
// every motor keeps its place on the path.
bool EbbTickClock::fit(double sixteenths_per_tick, uint32_t period_us) {
  stretch_q16_ = kUnstretchedQ16;
  const double carried = carried_per_tick(period_us);
  if (sixteenths_per_tick <= carried) return false;
  stretch_q16_ = static_cast<uint32_t>(ceil(sixteenths_per_tick / carried * kUnstretchedQ16));
  return true;
}

}  // namespace stepdance::ebb
