// The events due at one simulated time, in the order they were scheduled.
#pragma once

#include <cstddef>

#include "common/sim_time.hpp"

namespace stepdance::sim {

class Event;

/// A first-in first-out list of the events queued for `time`, threaded through the events
/// themselves. Many events share a time (a thousand boards tick their frames at the same
/// nanosecond), so the scheduler orders slots, not events.
struct TimeSlot {
  SimTime time = 0;
  Event* first = nullptr;  ///< scheduled first, handled first
  Event* last = nullptr;
  size_t heap_index = 0;  ///< place in the scheduler's heap of slots
};

}  // namespace stepdance::sim
