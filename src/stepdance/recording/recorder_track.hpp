// RecorderTrack: turns one input position into whole recorded steps, frame by frame.
#pragma once

#include <stdint.h>

#include "stepdance/core/block_port.hpp"
#include "stepdance/core/units.hpp"

namespace stepdance {

/// One track of a FourTrackRecorder. Its input port (world units) is scaled by the resolution
/// into steps (block units = recorded steps); each frame the track moves its own step counter
/// toward the input by whole steps, keeping a dead band of half a step, and returns the steps
/// taken. The original took at most one step per frame, so fast input lagged behind; here the
/// most per frame is a parameter (1 for the original format, up to 127 for ours).
class RecorderTrack {
 public:
  RecorderTrack();

  /// Begins the input port (an INPUT for deep sync, owned by `parent`). Context: loop.
  void begin(Block* parent);
  /// Recorded steps per world unit: `world_units` of input make `per_steps` steps. Context: loop.
  void set_resolution(double world_units, double per_steps = 1.0);
  /// World units per recorded step. Context: any.
  double resolution() const { return input_target_position.ratio(); }

  /// Pulls and updates the input. Context: frame ISR.
  void follow_input();
  /// Steps (−max_steps…max_steps) that bring the counter nearest the input; the counter moves
  /// by them. |input − counter| ≤ 0.5 step gives 0. Context: frame ISR.
  int32_t step_toward_input(int32_t max_steps);
  /// Sets the counter to the input's nearest step, so nothing before now is recorded.
  /// Context: frame ISR, or loop while the track's recorder is inactive.
  void sync_to_input();
  /// The step counter. Context: any.
  int64_t steps() const { return counter_; }

  /// The position being recorded (world units in, steps inside).
  BlockPort input_target_position;

 private:
  DecimalPosition target_steps_ = 0;
  int64_t counter_ = 0;
};

}  // namespace stepdance
