// Look-ahead over queued moves: junction limits, backward and forward passes, final blocks out.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "stepdance/core/status.hpp"
#include "stepdance/motion/planner/planned_block.hpp"

namespace stepdance::planner {

/// Plans the speeds of moves that have not yet reached the frame. Every add() re-runs a backward
/// pass (each move must be able to stop by the end of the known queue) and a forward pass (from
/// the speed the frame will have when it gets there). take_final() hands out the oldest block
/// once its exit speed can no longer rise with moves added later, or at once when the frame
/// would otherwise run dry — so 1,000 short collinear moves flow at full speed, and a stream
/// that stops ends in a controlled deceleration. Context: loop only.
class LookaheadPlanner {
 public:
  static constexpr size_t kCapacity = 128;

  /// Junction deviation δ in path units (default 0.02).
  void set_junction_deviation(double deviation) { junction_deviation_ = deviation; }
  double junction_deviation() const { return junction_deviation_; }

  /// Queues a block with delta, length, cruise_speed and acceleration set (length > 0) or a
  /// dwell (length 0, dwell_s > 0). kFull when kCapacity blocks wait (nothing changes).
  Status add(const PlannedBlock& block);
  /// Hands out the oldest block if its speeds are final, or regardless when `flush` is true.
  bool take_final(PlannedBlock& out, bool flush);

  size_t size() const { return count_; }
  size_t free_slots() const { return kCapacity - count_; }
  bool full() const { return count_ == kCapacity; }
  /// Forgets every waiting block; the next block starts from rest.
  void clear();

 private:
  size_t slot(size_t i) const { return (head_ + i) % kCapacity; }
  PlannedBlock& at(size_t i) { return blocks_[slot(i)]; }
  void replan();

  PlannedBlock blocks_[kCapacity];
  double stop_limit_[kCapacity] = {};  // per slot: entry speed that still allows every later stop
  size_t head_ = 0;
  size_t count_ = 0;
  double junction_deviation_ = 0.02;
  double committed_exit_speed_ = 0.0;  // exit speed of the last block handed out
  double last_direction_[3] = {};
  bool last_was_motion_ = false;  // false after a dwell, a clear or at start: next starts at rest
  double last_cruise_ = 0.0;
  double last_length_ = 0.0;
  double last_acceleration_ = 0.0;
};

}  // namespace stepdance::planner
