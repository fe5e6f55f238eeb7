// The discrete-event kernel's binary heap and its dispatch loop.
#include "scheduler/scheduler.hpp"

namespace stepdance::sim {

Scheduler::~Scheduler() {
  for (Event* event : heap_) event->heap_index_ = Event::kNotQueued;
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
  if (event.scheduled()) remove_at(event.heap_index_);
  event.time_ = time < now_ ? now_ : time;
  event.sequence_ = next_sequence_++;
  heap_.push_back(&event);
  event.heap_index_ = heap_.size() - 1;
  sift_up(event.heap_index_);
}

void Scheduler::cancel(Event& event) {
  if (event.scheduled()) remove_at(event.heap_index_);
}

bool Scheduler::step(SimTime end) {
  if (heap_.empty() || heap_.front()->time_ > end) return false;
  Event* const event = heap_.front();
  remove_at(0);
  if (event->time_ > now_) now_ = event->time_;
  ++handled_;
  if (event->handler_ != nullptr) event->handler_(*event, *this);
  return true;
}

void Scheduler::run_until(SimTime end) {
  while (step(end)) {
  }
  if (end > now_) now_ = end;
}

}  // namespace stepdance::sim
