// The time → slot hash table of the discrete-event kernel.
#include "kernel/scheduler/time_slot_index.hpp"

#include <cstdint>

namespace stepdance::sim {

// Fibonacci hashing: times are often multiples of a round number of ns, so the product's high
// bits, not the time's low bits, pick the cell.
size_t TimeSlotIndex::home(SimTime time) const {
  return static_cast<size_t>((static_cast<uint64_t>(time) * 0x9E3779B97F4A7C15ull) >> shift_);
}

TimeSlot* TimeSlotIndex::find(SimTime time) const {
  for (size_t cell = home(time); cells_[cell] != nullptr; cell = next(cell)) {
    if (cells_[cell]->time == time) return cells_[cell];
  }
  return nullptr;
}

void TimeSlotIndex::insert(TimeSlot* slot) {
  if (2 * (count_ + 1) > cells_.size()) grow();
  size_t cell = home(slot->time);
  while (cells_[cell] != nullptr) cell = next(cell);
  cells_[cell] = slot;
  ++count_;
}

// Backward-shift deletion: every slot after the hole in its cluster that would not be found from
// its home cell any more moves into the hole.
void TimeSlotIndex::erase(const TimeSlot* slot) {
  size_t hole = home(slot->time);
  while (cells_[hole] != slot) hole = next(hole);
  cells_[hole] = nullptr;
  --count_;
  for (size_t cell = next(hole); cells_[cell] != nullptr; cell = next(cell)) {
    const size_t wanted = home(cells_[cell]->time);
    // The slot may stay if its home lies cyclically in (hole, cell].
    const bool stays = hole < cell ? (hole < wanted && wanted <= cell) : (hole < wanted || wanted <= cell);
    if (stays) continue;
    cells_[hole] = cells_[cell];
    cells_[cell] = nullptr;
    hole = cell;
  }
}

void TimeSlotIndex::grow() {
  std::vector<TimeSlot*> old(cells_.size() * 2, nullptr);
  old.swap(cells_);
  --shift_;
  count_ = 0;
  for (TimeSlot* slot : old) {
    if (slot != nullptr) insert(slot);
  }
}

}  // namespace stepdance::sim
