// What travels between a board's ports and the rest of the simulation: played frames and arriving pulses.
#pragma once

#include "common/sim_time.hpp"
#include "stepdance/protocol/signals.hpp"

namespace stepdance::sim {

/// Receives the frames an output port plays on its STEP/DIR lines. Only frames with at least
/// one high bit are reported, unless the listener wants idle frames too; between reported frames
/// both lines are low.
class WireListener {
 public:
  virtual ~WireListener() = default;
  /// True if on_frame() must also be called for idle frames (all-zero words) at every frame
  /// tick, e.g. by a cable that injects glitches between frames. Asked once, when added.
  virtual bool wants_idle_frames() const { return false; }
  /// `words` play from `start_ns`: bit n is the level during [start + n µs, start + (n+1) µs),
  /// and both lines are low again from start + 32 µs (earlier in a shorter format). The next
  /// frame starts at start + frame_ns (the board's frame period). Called at `start_ns`, so a
  /// listener sees the whole frame up to 32 µs before its last edge (it must use the edge times,
  /// not now()).
  virtual void on_frame(SimTime start_ns, const protocol::FrameWords& words, SimTime frame_ns) = 0;
};

/// One STEP pulse as it reaches an input port's pins, after any cable effects.
struct ArrivingPulse {
  SimTime rise_ns = 0;
  SimTime fall_ns = 0;
  bool dir_at_rise = false;  ///< DIR level at the rising edge
  bool dir_at_fall = false;  ///< DIR level at the falling edge
};

}  // namespace stepdance::sim
