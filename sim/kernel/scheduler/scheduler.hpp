// The discrete-event kernel: one thread, one 64-bit nanosecond clock, events in (time, sequence) order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/sim_time.hpp"
#include "kernel/scheduler/event.hpp"

namespace stepdance::sim {

/// Runs events in strict (time, insertion sequence) order and jumps the clock from one event to
/// the next. Two runs that schedule the same events in the same order behave identically.
///
/// The queue is a binary heap of pointers to intrusive events, so scheduling allocates nothing
/// once the heap's storage has grown to the largest number of events pending at once.
class Scheduler {
 public:
  Scheduler() { heap_.reserve(64); }
  Scheduler(const Scheduler&) = delete;
  Scheduler& operator=(const Scheduler&) = delete;
  ~Scheduler();

  /// Current simulated time in ns: the time of the event being handled, or where run_until()
  /// stopped.
  SimTime now() const { return now_; }

  /// Queues `event` at `time` (never earlier than now(); earlier times are raised to now()).
  /// An event already queued is moved and gets a new sequence number.
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
  size_t pending() const { return heap_.size(); }
  /// Number of events handled since construction.
  uint64_t handled() const { return handled_; }
  /// Time of the earliest pending event, or `fallback` if the queue is empty.
  SimTime next_time(SimTime fallback) const { return heap_.empty() ? fallback : heap_.front()->time_; }

 private:
  void sift_up(size_t index);
  void sift_down(size_t index);
  void place(Event* event, size_t index);
  void remove_at(size_t index);

  std::vector<Event*> heap_;
  SimTime now_ = 0;
  uint64_t next_sequence_ = 0;
  uint64_t handled_ = 0;
  bool stopped_ = false;
};

}  // namespace stepdance::sim
