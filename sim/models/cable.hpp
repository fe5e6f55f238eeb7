// A TRRS cable between an output and an input port: delay, pulse stretch and glitch injection.
#pragma once

#include <cstdint>

#include "common/edges.hpp"
#include "common/sim_time.hpp"

namespace stepdance::sim {

/// What a cable does to the signals (all times in ns).
struct CableSettings {
  /// Propagation delay of both lines (≥ 0).
  SimTime delay = 0;
  /// Added to every STEP pulse's width by moving its falling edge (negative shrinks).
  SimTime stretch = 0;
  /// A glitch slot every this long, at k × glitch_every (k ≥ 1); 0 = no glitches.
  SimTime glitch_every = 0;
  /// Width of each injected glitch pulse (> 0).
  SimTime glitch_width = 500;
};

/// What the cable has done so far.
struct CableCounters {
  /// STEP pulses that entered the cable.
  uint64_t pulses_in = 0;
  /// STEP pulses delivered (pulses_in − pulses_removed − pulses_merged, once closed).
  uint64_t pulses_passed = 0;
  /// Pulses shrunk to nothing (width + stretch ≤ 0).
  uint64_t pulses_removed = 0;
  /// Pulses stretched into the next one and delivered together with it.
  uint64_t pulses_merged = 0;
  /// Glitch pulses added, and glitch slots skipped because a real pulse was there.
  uint64_t glitches_injected = 0;
  uint64_t glitches_skipped = 0;
};

/// Transforms a port's waveform window by window (e.g. one 40 µs frame at a time). Windows must
/// be passed in order and not overlap; the edges of a window must lie in it.
///   - Both lines are delayed by `delay`.
///   - Every STEP falling edge moves by `stretch`. A pulse shrunk to zero or less width is
///     removed; a pulse stretched to or past the next rising edge of the same window merges
///     with it. A pulse open at the end of a window keeps its state into the next one; its
///     falling edge then lands no earlier than that window's start (and at least 1 ns after its
///     rise, since the rising edge has already been sent). If a
///     stretched falling edge of one window reaches past the next window's first rising edge,
///     that edge is moved to 1 ns after it (stretch should stay below the 2 µs gap between pulses).
///   - Glitch slot g = k × glitch_every (k ≥ 1, input time) belongs to the window holding g. It
///     gets a STEP pulse [g, g + glitch_width] if that pulse ends strictly before the window does
///     and no (stretched) real pulse or earlier falling edge touches it; otherwise it is skipped.
class Cable {
 public:
  explicit Cable(const CableSettings& settings = {});

  /// The waveform seen at the far end for the input window [window_start, window_end) (input time).
  /// Output edges are in output time (input + delay), sorted, each changing its line's level.
  PortWaveform transmit(const PortWaveform& input, SimTime window_start, SimTime window_end);

  const CableSettings& settings() const { return settings_; }
  const CableCounters& counters() const { return counters_; }

 private:
  CableSettings settings_;
  CableCounters counters_;
  /// A STEP pulse still high at the end of the last window (its rise time, input time).
  bool open_pulse_ = false;
  SimTime open_rise_ = 0;
  /// Latest falling edge sent (input time), real or glitch.
  SimTime last_fall_ = -1;
};

}  // namespace stepdance::sim
