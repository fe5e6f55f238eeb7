// Decodes a captured STEP/DIR waveform pulse by pulse with the core's decode_pulse (`stepdance decode`).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/edges.hpp"
#include "common/sim_time.hpp"
#include "output/pulse_counts.hpp"
#include "stepdance/protocol/pulse_decoder.hpp"

namespace stepdance::sim {

/// How to decode a capture; the defaults are a Stepdance input port's.
struct DecodeOptions {
  /// STEPDANCE: axis by width, DIR at the STEP falling edge. STEP_DIR: every pulse of at least
  /// 1 µs is a step of step_dir_signal, DIR at the STEP rising edge.
  InputMode mode = INPUT_MODE_STEPDANCE;
  /// The signal STEP_DIR pulses count as.
  uint8_t step_dir_signal = SIGNAL_X;
  /// The capture timer the firmware measures widths with (150 ticks/µs, 16-bit counter).
  protocol::CaptureClock clock{};
  /// The sender's frame period in µs (10, 20, 25 or 40): how accepted pulses group into frames.
  uint32_t frame_period_us = 40;
  /// How many rejected pulses to keep as examples.
  size_t max_rejected_examples = 10;
};

/// The levels of STEP and DIR when the capture starts (before their first edges).
struct InitialLevels {
  bool step = false;
  bool dir = false;
};

/// A pulse decode_pulse rejected.
struct RejectedPulse {
  SimTime rise = 0;  ///< ns
  SimTime fall = 0;  ///< ns
  uint8_t width_us = 0;  ///< the width decode_pulse measured, rounded to µs (ties down)
  protocol::PulseVerdict reason = protocol::PulseVerdict::kTooShort;
};

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
  uint64_t count = 0;            ///< frames holding at least one accepted pulse
  uint32_t max_pulses = 0;       ///< most accepted pulses in one frame
  SimTime min_start_spacing = 0; ///< ns between consecutive frames' first rises (0 with < 2 frames)
  SimTime max_start_spacing = 0; ///< ns, as above
};

/// Everything decoded from one STEP/DIR pair.
struct DecodeResult {
  DecodeOptions options;          ///< the options used
  SignalCounts counts{};          ///< accepted pulses per signal and direction
  uint64_t accepted = 0;          ///< sum of counts
  uint64_t too_short = 0;         ///< rejected as shorter than the narrowest signal
  uint64_t too_long = 0;          ///< rejected as wider than the widest signal
  /// Pulses cut by the capture's edges: STEP already high at the start, or still high at the end.
  uint64_t incomplete = 0;
  std::vector<RejectedPulse> first_rejected;  ///< the first max_rejected_examples rejections
  FrameStats frames;
};

/// Decodes every complete STEP pulse exactly as an input port does: rise and fall times are
/// converted to capture ticks (ns × ticks_per_us / 1000, rounded half up), made a wrapped
/// capture with its whole counter periods (protocol::captured_from_ticks, as the Teensy backend
/// and the simulator report long pulses) and passed with the DIR level to protocol::decode_pulse. DIR is the level of its last
/// edge at or before the sampling STEP edge (an edge at the same ns counts as already happened).
/// Edges that do not change a line's level are ignored. Preconditions: edges in time order,
/// times ≥ 0. Pure.
DecodeResult decode_step_dir(const EdgeList& step, const EdgeList& dir, const DecodeOptions& options,
                             InitialLevels initial = {});

/// Capture-timer ticks at `time_ns` (rounded half up, not masked). Precondition: time_ns ≥ 0.
uint64_t capture_ticks(SimTime time_ns, uint32_t ticks_per_us);

}  // namespace stepdance::sim
