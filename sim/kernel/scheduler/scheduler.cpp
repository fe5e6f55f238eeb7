// The discrete-event kernel: slots of same-time events, their heap, and the dispatch loop.
#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim {

Scheduler::~Scheduler() {
  for (TimeSlot* slot : heap_) {
    for (Event* event = slot->first; event != nullptr; event = event->later_) event->slot_ = nullptr;
  }
}

// ---- the slots' heap, by time (no two slots share a time) -------------------------------------

void Scheduler::place(TimeSlot* slot, size_t index) {
  heap_[index] = slot;
  slot->heap_index = index;
}

void Scheduler::sift_up(size_t index) {
  TimeSlot* const moving = heap_[index];
  while (index > 0) {
    const size_t parent = (index - 1) / 2;
    if (heap_[parent]->time <= moving->time) break;
    place(heap_[parent], index);
    index = parent;
  }
  place(moving, index);
}

void Scheduler::sift_down(size_t index) {
  TimeSlot* const moving = heap_[index];
  const size_t size = heap_.size();
  for (;;) {
    size_t child = 2 * index + 1;
    if (child >= size) break;
    if (child + 1 < size && heap_[child + 1]->time < heap_[child]->time) ++child;
    if (heap_[child]->time >= moving->time) break;
    place(heap_[child], index);
    index = child;
  }
  place(moving, index);
}

TimeSlot* Scheduler::new_slot(SimTime time) {
  TimeSlot* slot = nullptr;
  if (free_slots_.empty()) {
    slot = &slots_.emplace_back();
  } else {
    slot = free_slots_.back();
    free_slots_.pop_back();
  }
  slot->time = time;
  slot->first = slot->last = nullptr;
  index_.insert(slot);
  heap_.push_back(slot);
  slot->heap_index = heap_.size() - 1;
  sift_up(slot->heap_index);
  return slot;
}

void Scheduler::free_slot(TimeSlot* slot) {
  index_.erase(slot);
  const size_t index = slot->heap_index;
  TimeSlot* const last = heap_.back();
  heap_.pop_back();
  if (last != slot) {
    place(last, index);
    sift_down(index);
    sift_up(last->heap_index);
  }
  free_slots_.push_back(slot);
}

// ---- events in their slots -----------------------------------------------------------------------

void Scheduler::append(Event& event, SimTime time) {
  TimeSlot* slot = index_.find(time);
  if (slot == nullptr) slot = new_slot(time);
  event.time_ = time;
  event.slot_ = slot;
  event.earlier_ = slot->last;
  event.later_ = nullptr;
  if (slot->last != nullptr) {
    slot->last->later_ = &event;
  } else {
    slot->first = &event;
  }
  slot->last = &event;
  ++pending_;
}

void Scheduler::unlink(Event& event) {
  TimeSlot* const slot = event.slot_;
  (event.earlier_ != nullptr ? event.earlier_->later_ : slot->first) = event.later_;
  (event.later_ != nullptr ? event.later_->earlier_ : slot->last) = event.earlier_;
  event.slot_ = nullptr;
  event.earlier_ = event.later_ = nullptr;
  --pending_;
  if (slot->first == nullptr) free_slot(slot);
}

void Scheduler::schedule(Event& event, SimTime time) {
  if (event.slot_ != nullptr) unlink(event);
  append(event, time < now_ ? now_ : time);
}

void Scheduler::cancel(Event& event) {
  if (event.slot_ != nullptr) unlink(event);
}

// The earliest slot's first event leaves the queue before its handler runs, so the handler may
// schedule it again, and a nested step() (a handler running the world, as delay() does) goes on
// with the events after it.
bool Scheduler::step(SimTime end) {
  if (heap_.empty() || heap_.front()->time > end) return false;
  Event* const event = heap_.front()->first;
  if (event->time_ > now_) now_ = event->time_;
  ++handled_;
  unlink(*event);
  if (event->handler_ != nullptr) event->handler_(*event, *this);
  return true;
}

void Scheduler::run_until(SimTime end) {
  while (!stopped_ && step(end)) {
  }
  if (!stopped_ && end > now_) now_ = end;
}

}  // namespace stepdance::sim
