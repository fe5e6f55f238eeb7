// A quadrature encoder knob: a schedule of turns, read as the hardware counter's value at any time.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/sim_time.hpp"

namespace stepdance::sim {

/// An incremental encoder on a quadrature counter (×4 decoding). Turns are scheduled in advance;
/// count_at() gives the counter value at any time. A turn of N counts over a span T moves the
/// count by one whole count at a time, the k-th count (k = 1..|N|) arriving k·T/|N| after the
/// turn starts (rounded up to the ns), so the last one lands exactly at the end. A turn with
/// T = 0 moves the whole N at its start. Overlapping turns add up.
class QuadratureEncoder {
 public:
  /// `pulses_per_revolution` per channel (×4 = counts per revolution); `start_count` at time 0.
  explicit QuadratureEncoder(int32_t pulses_per_revolution = 600, int64_t start_count = 0);

  /// Schedules a turn of `counts` (signed) starting at `start` (ns) and lasting `span` (ns, < 0 as 0).
  void turn(SimTime start, int64_t counts, SimTime span);

  /// Counter value at `time`. Fastest when successive calls have non-decreasing times.
  int64_t count_at(SimTime time) const;
  /// Counter value at `time` in revolutions from zero.
  double revolutions_at(SimTime time) const;

  /// Counts per revolution (4 × pulses per revolution; 2400 for a 600-pulse knob).
  int64_t counts_per_revolution() const { return int64_t{4} * pulses_per_revolution_; }
  int32_t pulses_per_revolution() const { return pulses_per_revolution_; }
  int64_t start_count() const { return start_count_; }

 private:
  struct Turn {
    SimTime start;
    SimTime end;
    int64_t counts;
  };
  /// Counts turn `turn` has delivered by `time`.
  static int64_t delivered(const Turn& turn, SimTime time);
  /// Restarts the forward cursor before any turn.
  void reset_cursor() const;

  int32_t pulses_per_revolution_;
  int64_t start_count_;
  /// Turns sorted by start time (stable).
  std::vector<Turn> turns_;

  // Forward cursor: turns_[0..next_) have started by cursor_time_; `active_` holds the unfinished
  // ones among them and `settled_` the total of the finished ones.
  mutable SimTime cursor_time_;
  mutable size_t next_ = 0;
  mutable int64_t settled_ = 0;
  mutable std::vector<size_t> active_;
};

}  // namespace stepdance::sim
