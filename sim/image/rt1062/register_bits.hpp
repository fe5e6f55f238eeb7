// Small helpers shared by the RT1062 register models: byte lanes of 32-bit registers, the
// SET/CLR/TOG aliases of the analog blocks, and a scheduler event that calls back into a model.
#pragma once

#include <cstdint>
#include <functional>
#include <utility>

#include "kernel/scheduler/event.hpp"
#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim::image::rt1062 {

/// The `bytes` (1, 2 or 4) of a 32-bit register `word` that an access at byte `offset` reads,
/// zero-extended. Context: any.
constexpr uint32_t lane_read(uint32_t word, uint32_t offset, uint8_t bytes) {
  const uint32_t shift = 8u * (offset & 3u);
  const uint32_t mask = bytes >= 4 ? 0xFFFFFFFFu : ((1u << (8u * bytes)) - 1u);
  return (word >> shift) & mask;
}

/// `word` with the `bytes` written at byte `offset` replaced by the low bytes of `value`.
constexpr uint32_t lane_merge(uint32_t word, uint32_t offset, uint8_t bytes, uint32_t value) {
  const uint32_t shift = 8u * (offset & 3u);
  const uint32_t mask = (bytes >= 4 ? 0xFFFFFFFFu : ((1u << (8u * bytes)) - 1u)) << shift;
  return (word & ~mask) | ((value << shift) & mask);
}

/// The analog blocks' register aliases (RM §14.8 and §13.4: every register has SET, CLR and TOG
/// addresses 4, 8 and 12 bytes above it; reading any of them reads the register).
enum class Alias : uint8_t { kWrite = 0, kSet = 1, kClear = 2, kToggle = 3 };

/// The new value of a register after a 32-bit write of `value` through `alias`.
constexpr uint32_t apply_alias(uint32_t old_value, Alias alias, uint32_t value) {
  switch (alias) {
    case Alias::kSet: return old_value | value;
    case Alias::kClear: return old_value & ~value;
    case Alias::kToggle: return old_value ^ value;
    case Alias::kWrite: break;
  }
  return value;
}

/// A scheduler event that calls a model's function when simulated time reaches it. Simulator
/// side only (the callback may allocate). Scheduling it again moves it.
class ModelEvent : public Event {
 public:
  explicit ModelEvent(std::function<void()> callback) : Event(&fire), callback_(std::move(callback)) {}

 private:
  static void fire(Event& event, Scheduler&) { static_cast<ModelEvent&>(event).callback_(); }
  std::function<void()> callback_;
};

}  // namespace stepdance::sim::image::rt1062
