// PositionGenerator: moves its output to a commanded position at a constant speed.
#pragma once

#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/core/units.hpp"

namespace stepdance {

/// Drives `output` toward a target at up to speed_units_per_sec, one frame at a time, and
/// lands exactly on it (constant velocity, no acceleration). Targets come from go() in the loop.
///
/// Units: positions and speeds are in the output port's world units (its ratio converts them
/// into the generator's own state).
///
/// A reset of the output (BlockPort::reset or reset_deep) shifts the target with it, so a reset
/// never produces motion: an idle generator stays idle, a moving one keeps its remaining distance.
class PositionGenerator : public Block {
 public:
  PositionGenerator();

  /// Begins the output (OUTPUT, for deep sync) and registers the block in the pre-channel
  /// stage. The state and target start at 0. kFull if that registry is full. Context: loop.
  Status begin();

  /// Sets the speed in world units per second (its magnitude is used). Context: any.
  void set_speed(double units_per_s) { speed_units_per_sec = static_cast<float>(units_per_s); }
  /// Sets a new target and the speed (world units, world units/s):
  ///   INCREMENTAL: target += value;
  ///   ABSOLUTE:    target = value, in the generator's own coordinates;
  ///   GLOBAL:      output.pull_deep() first (adopt the downstream machine position), then
  ///                target = value.
  /// Safe against the frame ISR (interrupts are held off while it runs). Context: loop.
  void go(double value, PositionMode mode, double speed_units_per_s);
  /// As go(value, mode, speed) with the stored speed. Context: loop.
  void go(double value, PositionMode mode);

  /// The current target in world units (including the shift of a reset). Context: any.
  double target() const;
  /// True when the output sits on the target (a reset does not change this). Context: any.
  bool is_idle() const { return last_set_ == target_; }

  /// One frame: step toward the target by at most speed × 40 µs, then set and push the output.
  /// Context: frame ISR.
  void run() override;

  /// The generated position (OUTPUT port; world units).
  BlockPort output;
  /// Travel speed in world units per second (written by set_speed, go, or an AnalogInput).
  ControlParameter speed_units_per_sec = 0;

 private:
  double max_step_block_units() const;
  void follow_output_reset();

  DecimalPosition position_ = 0;  // the output's state, block units
  DecimalPosition target_ = 0;    // block units
  DecimalPosition last_set_ = 0;  // position_ as this block last set it
};

}  // namespace stepdance
