// Finds the slot of a simulated time in O(1): an open-addressing hash table that allocates only
// when it grows.
#pragma once

#include <cstddef>
#include <vector>

#include "common/sim_time.hpp"
#include "kernel/scheduler/time_slot.hpp"

namespace stepdance::sim {

/// Maps each pending time to its slot (linear probing; removal shifts the cluster back, so there
/// are no tombstones). Holds at most half its capacity, doubling when it would hold more.
class TimeSlotIndex {
 public:
  TimeSlotIndex() : cells_(kInitialCapacity, nullptr) {}

  /// The slot of `time`, or nullptr.
  TimeSlot* find(SimTime time) const;
  /// Adds `slot` under slot->time (not present yet).
  void insert(TimeSlot* slot);
  /// Removes `slot` (present).
  void erase(const TimeSlot* slot);

 private:
  static constexpr size_t kInitialCapacity = 64;     // a power of two
  static constexpr unsigned kInitialShift = 64 - 6;  // 64 − log2(kInitialCapacity)
  size_t home(SimTime time) const;
  size_t next(size_t cell) const { return (cell + 1) & (cells_.size() - 1); }
  void grow();

  std::vector<TimeSlot*> cells_;
  unsigned shift_ = kInitialShift;  ///< 64 − log2(capacity): the hash's bits that pick a cell
  size_t count_ = 0;
};

}  // namespace stepdance::sim
