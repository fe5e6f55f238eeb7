// The discrete-event kernel: one thread, one 64-bit nanosecond clock, events in (time, scheduling order).
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <vector>

#include "common/sim_time.hpp"
#include "kernel/scheduler/event.hpp"
#include "kernel/scheduler/time_slot.hpp"
#include "kernel/scheduler/time_slot_index.hpp"

namespace stepdance::sim {

/// Runs events in strict (time, insertion sequence) order and jumps the clock from one event to
/// the next. Two runs that schedule the same events in the same order behave identically.
///
/// The events due at one time wait in that time's slot, first scheduled first (a list threaded
/// through the events); a binary heap orders the slots by time, and a hash table finds a time's
/// slot. Many events share a time (every board's frame tick), so scheduling one costs a lookup
/// and a list append, not a walk down a heap of every event. Scheduling allocates nothing once
/// the slots and tables have grown to the most distinct times pending at once.
class Scheduler {
 public:
  Scheduler() { heap_.reserve(64); }
  Scheduler(const Scheduler&) = delete;
  Scheduler& operator=(const Scheduler&) = delete;
  ~Scheduler();

  /// Current simulated time in ns: the time of the event being handled, or where run_until()
  /// stopped.
  SimTime now() const { return now_; }

  /// Queues `event` at `time` (never earlier than now(); earlier times are raised to now()),
  /// after every event already queued for that time. An event already queued is moved.
  void schedule(Event& event, SimTime time);
  /// Removes `event` from the queue if it is there.
  void cancel(Event& event);

  /// Handles every event with time ≤ `end`, then sets now() to `end`. May be called from inside
  /// a handler (an Arduino delay() runs the rest of the world this way); the nested call never
  /// moves the clock backwards.
  void run_until(SimTime end);
  /// Ends the run at the current event: every run_until(), nested ones included, returns after
  /// the event being handled, leaving now() at its time. For good: a stopped scheduler runs no
  /// more events through run_until().
  void stop() { stopped_ = true; }
  bool stopped() const { return stopped_; }
  /// Handles the single earliest event if its time is ≤ `end`; returns false if there is none.
  bool step(SimTime end);

  /// Number of events waiting.
  size_t pending() const { return pending_; }
  /// Number of events handled since construction.
  uint64_t handled() const { return handled_; }
  /// Time of the earliest pending event, or `fallback` if the queue is empty.
  SimTime next_time(SimTime fallback) const { return heap_.empty() ? fallback : heap_.front()->time; }

 private:
  /// Appends `event` to the slot of `time`, making the slot if there is none.
  void append(Event& event, SimTime time);
  /// Takes `event` out of its slot, freeing the slot when it empties.
  void unlink(Event& event);
  TimeSlot* new_slot(SimTime time);
  void free_slot(TimeSlot* slot);
  void sift_up(size_t index);
  void sift_down(size_t index);
  void place(TimeSlot* slot, size_t index);

  std::vector<TimeSlot*> heap_;  ///< the slots with events, earliest time at the root
  TimeSlotIndex index_;
  std::deque<TimeSlot> slots_;  ///< every slot ever made (stable addresses)
  std::vector<TimeSlot*> free_slots_;
  size_t pending_ = 0;
  SimTime now_ = 0;
  uint64_t handled_ = 0;
  bool stopped_ = false;
};

}  // namespace stepdance::sim
