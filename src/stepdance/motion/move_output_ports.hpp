// MoveOutputPorts: the eight outputs of a block that executes queued moves (the TBI, the EBB).
#pragma once

#include "stepdance/core/block_port.hpp"

namespace stepdance {

/// The outputs every move executor offers under the original library's names: six axes, the
/// fraction of the current move done and its duration. The deriving block begins them on its own
/// state in begin() and sets them in its frame. Context: read and map from the loop.
struct MoveOutputPorts {
  BlockPort output_x;
  BlockPort output_y;
  BlockPort output_z;
  BlockPort output_e;
  BlockPort output_r;
  BlockPort output_t;
  /// Fraction of the current move done, 0 → 1 (1 when idle).
  BlockPort output_parameter;
  /// Duration of the current move, seconds.
  BlockPort output_duration;
};

}  // namespace stepdance
