// One scheduled happening of the discrete-event kernel: a time, a tie-break sequence and a handler.
#pragma once

#include <cstddef>
#include <cstdint>

#include "common/sim_time.hpp"

namespace stepdance::sim {

class Scheduler;

/// An intrusive event. The scheduler never owns events: periodic timers embed one and reschedule
/// it from their handler, one-shot events come from an EventPool. An event is in the queue at
/// most once; scheduling it again moves it.
class Event {
 public:
  /// Called when simulated time reaches time(). The event is already out of the queue, so the
  /// handler may schedule it again.
  using Handler = void (*)(Event& event, Scheduler& scheduler);

  explicit Event(Handler handler = nullptr) : handler_(handler) {}
  Event(const Event&) = delete;
  Event& operator=(const Event&) = delete;

  /// The time the event is (or was last) scheduled for, in ns.
  SimTime time() const { return time_; }
  /// True while the event waits in a scheduler's queue (not while its own handler runs, unless
  /// the handler scheduled it again).
  bool scheduled() const { return heap_index_ != kNotQueued && !in_dispatch_; }
  /// Replaces the handler (for pooled events that are reused for different jobs).
  void set_handler(Handler handler) { handler_ = handler; }

 private:
  friend class Scheduler;
  static constexpr size_t kNotQueued = static_cast<size_t>(-1);

  /// Strict (time, insertion sequence) order: earlier first, then first scheduled first.
  bool before(const Event& other) const {
    return time_ != other.time_ ? time_ < other.time_ : sequence_ < other.sequence_;
  }

  SimTime time_ = 0;
  uint64_t sequence_ = 0;
  size_t heap_index_ = kNotQueued;
  /// True while the handler runs and the event is still parked at the heap's root (see
  /// Scheduler::step): rescheduling it then is a cheap sift-down from the root.
  bool in_dispatch_ = false;
  Handler handler_;
};

}  // namespace stepdance::sim
