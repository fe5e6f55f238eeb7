// Capture decoder: pairs STEP edges into pulses, samples DIR, calls decode_pulse, groups frames.
#include "decode/capture_decoder.hpp"

#include <algorithm>

namespace stepdance::sim {
namespace {

/// Walks DIR forward through time, answering "level at t" for non-decreasing t.
class DirSampler {
 public:
  DirSampler(const EdgeList& edges, bool initial) : edges_(edges), level_(initial) {}

  bool at(SimTime time) {
    while (next_ < edges_.size() && edges_[next_].time <= time) level_ = edges_[next_++].level;
    return level_;
  }

 private:
  const EdgeList& edges_;
  size_t next_ = 0;
  bool level_;
};

/// Groups accepted pulses into frames as they arrive in time order.
class FrameGrouper {
 public:
  explicit FrameGrouper(uint32_t frame_period_us) : window_ns_(frame_window_ns(frame_period_us)) {}

  void add(SimTime rise, SimTime fall) {
    const bool new_frame = stats_.count == 0 || rise - last_fall_ > kFrameGapNs ||
                           rise - frame_start_ > window_ns_;
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

}  // namespace

uint64_t capture_ticks(SimTime time_ns, uint32_t ticks_per_us) {
  const uint64_t ns = static_cast<uint64_t>(time_ns);
  return ns / 1000 * ticks_per_us + (ns % 1000 * ticks_per_us + 500) / 1000;
}

DecodeResult decode_step_dir(const EdgeList& step, const EdgeList& dir, const DecodeOptions& options,
                             InitialLevels initial) {
  DecodeResult result;
  result.options = options;
  DirSampler dir_level(dir, initial.dir);
  FrameGrouper frames(options.frame_period_us);
  const protocol::DirSampleEdge sample_edge = protocol::dir_sample_edge(options.mode);
  const uint32_t ticks_per_us = options.clock.ticks_per_us;

  bool level = initial.step;
  bool have_rise = false;
  SimTime rise = 0;
  bool dir_at_rise = false;
  if (level) ++result.incomplete;  // already high: its rise was not captured
  for (const Edge& edge : step) {
    if (edge.level == level) continue;
    level = edge.level;
    if (level) {
      have_rise = true;
      rise = edge.time;
      dir_at_rise = dir_level.at(rise);
      continue;
    }
    if (!have_rise) continue;
    have_rise = false;
    const SimTime fall = edge.time;
    const bool dir_high = sample_edge == protocol::DirSampleEdge::kRising ? dir_at_rise : dir_level.at(fall);
    const protocol::CapturedPulse pulse = protocol::captured_from_ticks(
        capture_ticks(rise, ticks_per_us), capture_ticks(fall, ticks_per_us), dir_high, options.clock);
    const protocol::DecodedPulse decoded =
        protocol::decode_pulse(pulse, options.clock, options.mode, options.step_dir_signal);
    if (decoded.verdict == protocol::PulseVerdict::kAccepted) {
      DirectionCounts& counts = result.counts[decoded.signal];
      ++(decoded.direction > 0 ? counts.forward : counts.reverse);
      ++result.accepted;
      frames.add(rise, fall);
      continue;
    }
    ++(decoded.verdict == protocol::PulseVerdict::kTooLong ? result.too_long : result.too_short);
    if (result.first_rejected.size() < options.max_rejected_examples) {
      result.first_rejected.push_back(RejectedPulse{rise, fall, decoded.width_us, decoded.verdict});
    }
  }
  if (have_rise) ++result.incomplete;  // still high at the end
  result.frames = frames.stats();
  return result;
}

}  // namespace stepdance::sim
