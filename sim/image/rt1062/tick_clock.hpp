// Converts between simulated time and the ticks of a counter clocked at source_hz / divider,
// counted from an origin. Exact integer arithmetic (128-bit intermediates), so reruns agree.
#pragma once

#include <cstdint>

#include "common/sim_time.hpp"

namespace stepdance::sim::image::rt1062 {

/// A counter's clock: ticks since `origin_ns` at `source_hz` / `divider`. Tick n happens at the
/// first ns at or after origin + n × divider / source_hz s. Simulator side; context: any.
class TickClock {
 public:
  TickClock() = default;
  TickClock(SimTime origin_ns, uint32_t source_hz, uint32_t divider)
      : origin_ns_(origin_ns), source_hz_(source_hz), divider_(divider == 0 ? 1 : divider) {}

  /// False if the source has no clock (nothing ever ticks).
  bool running() const { return source_hz_ != 0; }
  SimTime origin_ns() const { return origin_ns_; }
  /// Whole ticks from the origin to `time_ns` (0 before the origin).
  uint64_t ticks_at(SimTime time_ns) const {
    if (!running() || time_ns <= origin_ns_) return 0;
    const unsigned __int128 elapsed = static_cast<uint64_t>(time_ns - origin_ns_);
    return static_cast<uint64_t>(elapsed * source_hz_ / (static_cast<unsigned __int128>(kSecond) * divider_));
  }
  /// The time of tick `ticks` (ns); the far future when the clock is stopped.
  SimTime time_of(uint64_t ticks) const {
    if (!running()) return INT64_MAX;
    const unsigned __int128 scaled = static_cast<unsigned __int128>(ticks) * kSecond * divider_;
    const unsigned __int128 ns = (scaled + source_hz_ - 1) / source_hz_;
    const unsigned __int128 limit = static_cast<unsigned __int128>(INT64_MAX - origin_ns_);
    return ns >= limit ? INT64_MAX : origin_ns_ + static_cast<SimTime>(ns);
  }

 private:
  SimTime origin_ns_ = 0;
  uint32_t source_hz_ = 0;
  uint32_t divider_ = 1;
};

}  // namespace stepdance::sim::image::rt1062
