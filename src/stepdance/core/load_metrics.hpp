// Frame-ISR load statistics: last, peak and average cycles, and overrun count, without overflow.
#pragma once

#include <stdint.h>

namespace stepdance {

/// Per-frame CPU cost statistics. Cycle totals are 64-bit, so they cannot overflow in practice
/// (2^64 cycles at 600 MHz is ~975 years).
class LoadMetrics {
 public:
  /// Records one frame that took `cycles`, against a budget of `budget_cycles` per frame.
  /// A frame over budget counts as an overrun. Context: frame ISR.
  void record(uint32_t cycles, uint32_t budget_cycles) {
    last_cycles_ = cycles;
    if (cycles > peak_cycles_) peak_cycles_ = cycles;
    total_cycles_ += cycles;
    ++frames_;
    if (cycles > budget_cycles) ++overruns_;
    budget_cycles_ = budget_cycles;
  }
  /// Clears everything. Context: loop.
  void reset() { *this = LoadMetrics(); }

  uint32_t last_cycles() const { return last_cycles_; }
  uint32_t peak_cycles() const { return peak_cycles_; }
  uint64_t total_cycles() const { return total_cycles_; }
  uint64_t frames() const { return frames_; }
  /// Frames that took longer than the frame period.
  uint32_t overruns() const { return overruns_; }
  /// Peak cycles as a fraction of the frame budget (0 before the first frame).
  double peak_fraction() const { return budget_cycles_ ? double(peak_cycles_) / budget_cycles_ : 0.0; }
  /// Mean cycles per frame as a fraction of the budget (0 before the first frame).
  double average_fraction() const {
    return (frames_ && budget_cycles_) ? double(total_cycles_) / double(frames_) / budget_cycles_ : 0.0;
  }

 private:
  uint32_t last_cycles_ = 0;
  uint32_t peak_cycles_ = 0;
  uint32_t budget_cycles_ = 0;
  uint32_t overruns_ = 0;
  uint64_t total_cycles_ = 0;
  uint64_t frames_ = 0;
};

}  // namespace stepdance
