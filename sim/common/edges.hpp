// Digital line edges: how STEP/DIR waveforms travel between ports, cables, devices and VCD files.
#pragma once

#include <cstdint>
#include <vector>

#include "common/sim_time.hpp"

namespace stepdance::sim {

/// A change of a digital line's level at a moment.
struct Edge {
  SimTime time = 0;
  bool level = false;
};

/// The edges of one line in time order (each edge changes the level).
using EdgeList = std::vector<Edge>;

/// The two lines of a motion-stream port over some span of time.
struct PortWaveform {
  EdgeList step;
  EdgeList dir;
};

/// A line's level at `time`: the level of the last edge at or before `time`, else `initial`.
/// Precondition: edges sorted by time.
inline bool level_at(const EdgeList& edges, SimTime time, bool initial = false) {
  bool level = initial;
  for (const Edge& edge : edges) {
    if (edge.time > time) break;
    level = edge.level;
  }
  return level;
}

}  // namespace stepdance::sim
