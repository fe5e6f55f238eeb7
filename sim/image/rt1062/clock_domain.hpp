// A peripheral clock counted against simulated time: whole cycles since an epoch, and back.
#pragma once

#include <cstdint>

#include "common/sim_time.hpp"

namespace stepdance::sim::image {

/// A clock of `hz` cycles per second that started counting at `epoch_ns`. Exact integer
/// arithmetic (no drift over hours), no overflow for any time a simulation reaches.
struct ClockDomain {
  SimTime epoch_ns = 0;
  uint32_t hz = 0;

  /// Cycles completed by `now_ns` (floor; 0 before the epoch). Context: any.
  int64_t cycles_at(SimTime now_ns) const {
    if (hz == 0 || now_ns <= epoch_ns) return 0;
    const int64_t elapsed_ns = now_ns - epoch_ns;
    const int64_t whole_s = elapsed_ns / kSecond;
    const int64_t rest_ns = elapsed_ns % kSecond;
    return whole_s * hz + rest_ns * static_cast<int64_t>(hz) / kSecond;
  }
  /// The first time (ns) at which `cycles` have completed: the inverse of cycles_at (ceil).
  /// Context: any.
  SimTime time_of(int64_t cycles) const {
    if (hz == 0 || cycles <= 0) return epoch_ns;
    const int64_t whole_s = cycles / hz;
    const int64_t rest = cycles % hz;
    return epoch_ns + whole_s * kSecond + (rest * kSecond + hz - 1) / hz;
  }
  /// `cycles` of this clock as a duration in ns, rounded to the nearest ns. Context: any.
  SimTime duration_ns(int64_t cycles) const {
    if (hz == 0) return 0;
    const int64_t whole_s = cycles / hz;
    const int64_t rest = cycles % hz;
    return whole_s * kSecond + (rest * kSecond + hz / 2) / hz;
  }
};

}  // namespace stepdance::sim::image
