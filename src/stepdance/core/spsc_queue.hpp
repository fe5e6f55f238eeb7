// A bounded single-producer/single-consumer queue, safe between one ISR and the loop.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include <atomic>

#include "stepdance/core/status.hpp"

namespace stepdance {

/// Lock-free ring buffer for exactly one producer context and one consumer context
/// (for example: a frame ISR producing, the loop consuming, or the reverse).
/// Holds up to Capacity items. When full, push() refuses with Status::kFull and the caller
/// decides (back-pressure); nothing already queued is ever overwritten.
template <typename T, size_t Capacity>
class SpscQueue {
 public:
  static_assert(Capacity > 0, "an SpscQueue needs room for at least one item");

  /// Producer side. Returns kFull (and changes nothing) when the queue is full.
  Status push(const T& item) {
    const uint32_t head = head_.load(std::memory_order_relaxed);
    const uint32_t tail = tail_.load(std::memory_order_acquire);
    if (head - tail == Capacity) {
      ++refused_;
      return Status::kFull;
    }
    slots_[head % Capacity] = item;
    head_.store(head + 1, std::memory_order_release);
    const uint32_t depth = head + 1 - tail;
    if (depth > high_water_) high_water_ = depth;
    return Status::kOk;
  }

  /// Consumer side. Returns kEmpty (out untouched) when there is nothing to take.
  Status pop(T& out) {
    const uint32_t tail = tail_.load(std::memory_order_relaxed);
    const uint32_t head = head_.load(std::memory_order_acquire);
    if (head == tail) return Status::kEmpty;
    out = slots_[tail % Capacity];
    tail_.store(tail + 1, std::memory_order_release);
    return Status::kOk;
  }

  /// Number of queued items (exact for the consumer, a lower bound for the producer).
  size_t size() const { return head_.load(std::memory_order_acquire) - tail_.load(std::memory_order_acquire); }
  bool empty() const { return size() == 0; }
  bool full() const { return size() == Capacity; }
  static constexpr size_t capacity() { return Capacity; }
  /// Deepest the queue has been since construction (producer's view).
  uint32_t high_water() const { return high_water_; }
  /// How many pushes were refused because the queue was full.
  uint32_t refused() const { return refused_; }

 private:
  // Capacity must divide 2^32 so the free-running indices stay consistent when they wrap.
  static_assert((Capacity & (Capacity - 1)) == 0, "SpscQueue capacity must be a power of two");
  T slots_[Capacity] = {};
  std::atomic<uint32_t> head_{0};
  std::atomic<uint32_t> tail_{0};
  uint32_t high_water_ = 0;
  uint32_t refused_ = 0;
};

}  // namespace stepdance
