// The channels an output drives and their ratios: where interfaces that speak in motor steps
// (the EBB's step counts, Grbl's $100–$102) take their steps per millimetre from.
#pragma once

#include "stepdance/core/block_port.hpp"

namespace stepdance {

/// World units (mm) per step of the channels found, and whether they agree.
struct ChannelRatios {
  /// Closer ratios than this (relative) are the same: set_ratio() callers often pass floats.
  static constexpr double kSameRatio = 1e-6;
  int found = 0;
  double mm_per_step = 0.0;  ///< the first channel's, in world units per channel step
  bool disagree = false;     ///< a later channel's ratio differs from the first's

  /// Adds one channel's ratio (world units per step; the sign, an inverted axis, is dropped).
  void add(double ratio);
  /// Whether `mm_per_step_given` is the same as the channels' ratio.
  bool agrees_with(double mm_per_step_given) const;
};

/// Adds the ratio of every channel `output` drives: one mapped to it directly, one its peer's
/// block (a kinematics) feeds from an output, or one whose input it is mapped to. A channel is
/// any block whose Block::world_units_per_step() answers for that port (no type names, no RTTI).
/// Context: loop (walks the port registry; meant for dance_start's checks).
void collect_channel_ratios(const BlockPort& output, ChannelRatios& ratios);

}  // namespace stepdance
