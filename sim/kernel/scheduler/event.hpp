// One scheduled happening of the discrete-event kernel: a time, a place in its time's queue and a
// handler.
#pragma once

#include <cstddef>
#include <cstdint>

#include "common/sim_time.hpp"

namespace stepdance::sim {

class Scheduler;
struct TimeSlot;

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
  bool scheduled() const { return slot_ != nullptr; }
  /// Replaces the handler (for pooled events that are reused for different jobs).
  void set_handler(Handler handler) { handler_ = handler; }

 private:
  friend class Scheduler;

  SimTime time_ = 0;
  /// The queue of events due at time_ that holds this one, while it is queued.
  TimeSlot* slot_ = nullptr;
  /// Neighbours in that queue: the event scheduled just before this one for the same time, and
  /// the one just after.
  Event* earlier_ = nullptr;
  Event* later_ = nullptr;
  Handler handler_;
};

}  // namespace stepdance::sim
