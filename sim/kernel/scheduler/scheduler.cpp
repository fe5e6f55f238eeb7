// The discrete-event kernel's binary heap and its dispatch loop.
#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim {

Scheduler::~Scheduler() {
  for (Event* event : heap_) {
    event->heap_index_ = Event::kNotQueued;
    event->in_dispatch_ = false;
  }
}

void Scheduler::place(Event* event, size_t index) {
  heap_[index] = event;
  event->heap_index_ = index;
}

void Scheduler::sift_up(size_t index) {
  Event* const moving = heap_[index];
  while (index > 0) {
    const size_t parent = (index - 1) / 2;
    if (!moving->before(*heap_[parent])) break;
    place(heap_[parent], index);
    index = parent;
  }
  place(moving, index);
}

void Scheduler::sift_down(size_t index) {
  Event* const moving = heap_[index];
  const size_t size = heap_.size();
  for (;;) {
    size_t child = 2 * index + 1;
    if (child >= size) break;
    if (child + 1 < size && heap_[child + 1]->before(*heap_[child])) ++child;
    if (!heap_[child]->before(*moving)) break;
    place(heap_[child], index);
    index = child;
  }
  place(moving, index);
}

void Scheduler::remove_at(size_t index) {
  Event* const removed = heap_[index];
  Event* const last = heap_.back();
  heap_.pop_back();
  removed->heap_index_ = Event::kNotQueued;
  if (last == removed) return;
  place(last, index);
  sift_down(index);
  sift_up(last->heap_index_);
}

void Scheduler::schedule(Event& event, SimTime time) {
  const bool parked_at_root = event.in_dispatch_;
  event.in_dispatch_ = false;
  const SimTime due = time < now_ ? now_ : time;
  if (parked_at_root) {
    // The event being handled sits at the root and its new key (due ≥ now, fresh sequence)
    // is larger than before: one sift-down replaces a pop and a push.
    event.time_ = due;
    event.sequence_ = next_sequence_++;
    sift_down(0);
    return;
  }
  if (event.heap_index_ != Event::kNotQueued) remove_at(event.heap_index_);
  event.time_ = due;
  event.sequence_ = next_sequence_++;
  heap_.push_back(&event);
  event.heap_index_ = heap_.size() - 1;
  sift_up(event.heap_index_);
}

void Scheduler::cancel(Event& event) {
  event.in_dispatch_ = false;
  if (event.heap_index_ != Event::kNotQueued) remove_at(event.heap_index_);
}

// The event stays at the root while its handler runs (no element can sort before it: every
// other key is later in time or in sequence). If the handler reschedules it, schedule() moves
// it down from there; otherwise it is removed afterwards. A nested step() (a handler running
// the world, as delay() does) first removes any such parked event.
bool Scheduler::step(SimTime end) {
  if (!heap_.empty() && heap_.front()->in_dispatch_) cancel(*heap_.front());
  if (heap_.empty() || heap_.front()->time_ > end) return false;
  Event* const event = heap_.front();
  if (event->time_ > now_) now_ = event->time_;
  ++handled_;
  event->in_dispatch_ = true;
  if (event->handler_ != nullptr) event->handler_(*event, *this);
  if (event->in_dispatch_) cancel(*event);
  return true;
}

void Scheduler::run_until(SimTime end) {
  while (!stopped_ && step(end)) {
  }
  if (!stopped_ && end > now_) now_ = end;
}

}  // namespace stepdance::sim
