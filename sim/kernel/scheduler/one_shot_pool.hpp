// Pooled one-shot events carrying a small payload (pulse deliveries, timeline actions).
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "common/sim_time.hpp"
#include "kernel/scheduler/event.hpp"
#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim {

/// Posts payloads to a callback at chosen times. Each post takes an event from a free list, so
/// once the pool has grown to the largest number of posts pending at once, posting allocates
/// nothing. Payload must be copyable.
template <typename Payload>
class OneShotPool {
 public:
  /// Called at the posted time with the posted payload.
  using Callback = void (*)(void* context, SimTime time, const Payload& payload);

  OneShotPool(Scheduler& scheduler, Callback callback, void* context)
      : scheduler_(scheduler), callback_(callback), context_(context) {}
  OneShotPool(const OneShotPool&) = delete;
  OneShotPool& operator=(const OneShotPool&) = delete;
  /// Withdraws every post still pending.
  ~OneShotPool() {
    for (auto& chunk : chunks_) {
      for (size_t i = 0; i < kChunkSlots; ++i) scheduler_.cancel(chunk[i]);
    }
  }

  /// Delivers `payload` to the callback at `time_ns` (raised to now if earlier).
  void post(SimTime time_ns, const Payload& payload) {
    Slot& slot = take();
    slot.payload = payload;
    scheduler_.schedule(slot, time_ns);
  }
  /// Number of events the pool owns (pending or free).
  size_t capacity() const { return chunks_.size() * kChunkSlots; }

 private:
  static constexpr size_t kChunkSlots = 256;

  struct Slot : Event {
    Slot() : Event(&fire) {}
    Payload payload{};
    OneShotPool* pool = nullptr;
  };

  Slot& take() {
    if (free_.empty()) grow();
    Slot* slot = free_.back();
    free_.pop_back();
    return *slot;
  }

  void grow() {
    chunks_.push_back(std::make_unique<Slot[]>(kChunkSlots));
    free_.reserve(capacity());
    Slot* chunk = chunks_.back().get();
    for (size_t i = kChunkSlots; i > 0; --i) {
      chunk[i - 1].pool = this;
      free_.push_back(&chunk[i - 1]);
    }
  }

  static void fire(Event& event, Scheduler& scheduler) {
    auto& slot = static_cast<Slot&>(event);
    OneShotPool& pool = *slot.pool;
    const Payload payload = slot.payload;
    pool.free_.push_back(&slot);
    pool.callback_(pool.context_, scheduler.now(), payload);
  }

  Scheduler& scheduler_;
  Callback callback_;
  void* context_;
  std::vector<std::unique_ptr<Slot[]>> chunks_;
  std::vector<Slot*> free_;
};

}  // namespace stepdance::sim
