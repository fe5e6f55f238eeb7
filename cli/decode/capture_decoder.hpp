// Decodes a captured STEP/DIR waveform pulse by pulse with the core's decode_pulse (`stepdance decode`).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/edges.hpp"
#include "common/sim_time.hpp"
#include "decode/frame_grouper.hpp"
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
  SimTime rise = 0;      ///< ns
  SimTime fall = 0;      ///< ns
  uint8_t width_us = 0;  ///< the width decode_pulse measured, rounded to µs (ties down)
  protocol::PulseVerdict reason = protocol::PulseVerdict::kTooShort;
};

/// Everything decoded from one STEP/DIR pair.
struct DecodeResult {
  DecodeOptions options;  ///< the options used
  PulseCounts counts;     ///< accepted pulses per signal and direction, rejected ones by reason
  uint64_t accepted = 0;  ///< sum of the accepted counts
  /// Pulses cut by the capture's edges: STEP already high at the start, or still high at the end.
  uint64_t incomplete = 0;
  std::vector<RejectedPulse> first_rejected;  ///< the first max_rejected_examples rejections
  FrameStats frames;
};

/// Decodes one STEP/DIR pair edge by edge, as a capture is read: memory stays the same however
/// long the capture (the first max_rejected_examples rejections are the only list kept). Gives
/// exactly what decode_step_dir gives for the same edges. Context: host, one thread.
class StepDirDecoder {
 public:
  StepDirDecoder(const DecodeOptions& options, InitialLevels initial);

  /// The next edge of STEP or DIR. Edges come in time order across both lines; at equal times
  /// in any order, for DIR's last edge at a time counts for every STEP edge at that time (its
  /// level is the level of its last edge at or before the STEP edge). An edge that does not
  /// change its line's level is ignored.
  void step_edge(SimTime time_ns, bool level);
  void dir_edge(SimTime time_ns, bool level);
  /// The result: a pulse still high counts as incomplete. Call once, after the last edge.
  DecodeResult finish();

 private:
  /// Decodes the STEP edges held at pending_time_, now that DIR's level there is final.
  void flush();
  void apply_step(SimTime time_ns, bool level);

  DecodeResult result_;
  protocol::DirSampleEdge sample_edge_;
  bool dir_level_;
  bool level_;  ///< STEP's level after the edges decoded so far
  bool have_rise_ = false;
  SimTime rise_ = 0;
  bool dir_at_rise_ = false;
  // STEP edges at one time wait for DIR's last edge at that time: they alternate, so the first
  // level and a count describe them all.
  SimTime pending_time_ = 0;
  bool pending_first_ = false;
  uint64_t pending_count_ = 0;
  bool pending_level_;  ///< STEP's level after the pending edges
  FrameGrouper frames_;
};

/// Decodes every complete STEP pulse exactly as an input port does: rise and fall times are
/// converted to capture ticks (ns × ticks_per_us / 1000, rounded half up), made a wrapped
/// capture with its whole counter periods (protocol::captured_from_ticks, as the Teensy backend
/// and the simulator report long pulses) and passed with the DIR level to protocol::decode_pulse. DIR is the level of
/// its last edge at or before the sampling STEP edge (an edge at the same ns counts as already happened). Edges that do
/// not change a line's level are ignored. Preconditions: edges in time order, times ≥ 0. Pure.
DecodeResult decode_step_dir(const EdgeList& step, const EdgeList& dir, const DecodeOptions& options,
                             InitialLevels initial = {});

/// Capture-timer ticks at `time_ns` (rounded half up, not masked). Precondition: time_ns ≥ 0.
uint64_t capture_ticks(SimTime time_ns, uint32_t ticks_per_us);

}  // namespace stepdance::sim
