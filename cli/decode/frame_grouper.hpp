// Accepted pulses grouped into the sender's frames, as they arrive in time order.
#pragma once

#include <algorithm>
#include <cstdint>

#include "common/sim_time.hpp"

namespace stepdance::sim {

/// A new frame starts when the gap from the previous accepted pulse's falling edge to the next
/// rising edge exceeds this (ns): within a frame the gaps are 2 µs.
constexpr SimTime kFrameGapNs = 8 * kMicrosecond;
/// A new frame also starts when a pulse rises more than this (ns) after the frame's first rise:
/// 4/5 of the period (32 µs at 40 µs, 8 µs at 10 µs). Every frame's first pulse rises at the same
/// offset, one period after the last frame's, and a frame's pulses rise within the period less
/// 4 µs of its first. At 10 µs the gap alone would not tell frames apart (it can be 3 µs).
constexpr SimTime frame_window_ns(uint32_t frame_period_us) {
  return static_cast<SimTime>(frame_period_us) * kMicrosecond * 4 / 5;
}

/// Accepted pulses grouped into frames by kFrameGapNs and frame_window_ns().
struct FrameStats {
  uint64_t count = 0;             ///< frames holding at least one accepted pulse
  uint32_t max_pulses = 0;        ///< most accepted pulses in one frame
  SimTime min_start_spacing = 0;  ///< ns between consecutive frames' first rises (0 with < 2 frames)
  SimTime max_start_spacing = 0;  ///< ns, as above
};

/// Groups accepted pulses into frames by kFrameGapNs and frame_window_ns() as they arrive in
/// time order. Context: host, one thread.
class FrameGrouper {
 public:
  explicit FrameGrouper(uint32_t frame_period_us) : window_ns_(frame_window_ns(frame_period_us)) {}

  /// The next accepted pulse, rising at `rise` and falling at `fall` (ns).
  void add(SimTime rise, SimTime fall) {
    const bool new_frame = stats_.count == 0 || rise - last_fall_ > kFrameGapNs || rise - frame_start_ > window_ns_;
    if (new_frame) {
      if (stats_.count > 0) {
        const SimTime spacing = rise - frame_start_;
        stats_.min_start_spacing = stats_.count == 1 ? spacing : std::min(stats_.min_start_spacing, spacing);
        stats_.max_start_spacing = std::max(stats_.max_start_spacing, spacing);
      }
      ++stats_.count;
      frame_start_ = rise;
      pulses_in_frame_ = 0;
    }
    ++pulses_in_frame_;
    stats_.max_pulses = std::max(stats_.max_pulses, pulses_in_frame_);
    last_fall_ = fall;
  }

  const FrameStats& stats() const { return stats_; }

 private:
  SimTime window_ns_;
  FrameStats stats_;
  SimTime frame_start_ = 0;
  SimTime last_fall_ = 0;
  uint32_t pulses_in_frame_ = 0;
};

}  // namespace stepdance::sim
