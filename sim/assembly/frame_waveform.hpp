// Turns one played frame (STEP/DIR words at a start time) into timed edges, and finds its STEP rises.
#pragma once

#include "common/edges.hpp"
#include "common/sim_time.hpp"
#include "stepdance/protocol/signals.hpp"

namespace stepdance::sim {

/// Replaces `out` with the edges of `words` played from `start_ns`: each line starts low, bit n
/// holds during [start + n µs, start + (n+1) µs), and a line still high after bit 31 falls at
/// start + 32 µs.
void frame_waveform(SimTime start_ns, const protocol::FrameWords& words, PortWaveform& out);

/// Calls on_rise(time_ns, dir_high) for every STEP rising edge of `words` played from
/// `start_ns`, with the DIR level during the microsecond the pulse starts.
template <typename OnRise>
void for_each_step_rise(SimTime start_ns, const protocol::FrameWords& words, OnRise&& on_rise) {
  // A rise is a high bit whose previous bit (or the idle line before bit 0) is low.
  uint32_t rises = words.step_bits & ~(words.step_bits << 1);
  while (rises != 0) {
    const int bit = __builtin_ctz(rises);
    rises &= rises - 1;
    on_rise(start_ns + SimTime{bit} * kMicrosecond, ((words.dir_bits >> bit) & 1u) != 0);
  }
}

}  // namespace stepdance::sim
