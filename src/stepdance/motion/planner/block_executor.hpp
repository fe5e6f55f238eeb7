// Follows committed blocks frame by frame: speed within the profile, exact end points.
#pragma once

#include <stdint.h>

#include "stepdance/core/spsc_queue.hpp"
#include "stepdance/motion/planner/planned_block.hpp"

namespace stepdance::planner {

/// Blocks the loop has committed to the frame (capacity 32, a power of two).
using CommittedQueue = SpscQueue<PlannedBlock, 32>;

/// The frame side of the planner. Each frame it moves along the current block at a speed that
/// (1) never exceeds the block's cruise speed × override, (2) changes by at most the block's
/// acceleration × time, and (3) always still allows reaching the block's exit speed (scaled by
/// the override when it is below 1) by the end. Time left over when a block ends in mid-frame
/// is spent on the next one, so short blocks do not lose a frame each. Every block ends
/// exactly at start + delta, whatever the override did. Context: frame ISR only.
class BlockExecutor {
 public:
  /// Advances by dt_s seconds, taking blocks from `queue` as needed. `position` holds each
  /// axis's current position (world units) and receives the new one; a block starts from where
  /// the position is when it loads and ends exactly on its `end`.
  void advance(double dt_s, double override_factor, CommittedQueue& queue, double (&position)[kPlannerAxes]);

  /// Decelerate to rest within the current block's acceleration, then drop every committed block.
  void request_stop() { stopping_ = true; }
  /// Stop now and drop every committed block (emergency).
  void stop_now(CommittedQueue& queue);

  bool idle() const { return !active_; }
  bool stopping() const { return stopping_; }
  /// Fraction of the current block done (0→1); 1 when idle.
  double parameter() const;
  /// Planned duration of the current block at override 1, seconds.
  double duration_s() const { return duration_s_; }
  /// Speed along the path now, units/s.
  double speed() const { return speed_; }
  /// Times a block ended at speed with no successor committed (the loop fell behind).
  uint32_t underruns() const { return underruns_; }
  /// Blocks completed since start.
  uint32_t completed() const { return completed_; }

 private:
  bool load(CommittedQueue& queue, const double (&position)[kPlannerAxes]);
  void place(double fraction, double (&position)[kPlannerAxes]) const;
  double advance_block(double dt_s, double override_factor, double (&position)[kPlannerAxes]);
  void finish_block(double (&position)[kPlannerAxes]);
  void drop_all(CommittedQueue& queue);

  PlannedBlock block_;
  bool active_ = false;
  bool stopping_ = false;
  double travelled_ = 0.0;           // along the current block, units
  double start_[kPlannerAxes] = {};  // position of each axis when the current block loaded
  double speed_ = 0.0;
  double dwell_left_s_ = 0.0;
  double duration_s_ = 0.0;
  uint32_t underruns_ = 0;
  uint32_t completed_ = 0;
};

/// Trapezoid time of a block at override 1: entry → cruise → exit at its acceleration.
/// Context: any (pure).
double block_time_s(const PlannedBlock& block);

}  // namespace stepdance::planner
