// PositionGenerator: moves its output to a commanded position at a constant speed.
#pragma once

#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/spsc_queue.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/core/units.hpp"

namespace stepdance {

/// Drives `output` toward a target at up to speed_units_per_sec, one frame at a time, and
/// lands exactly on it (constant velocity, no acceleration). Targets come from go() in the loop
/// and reach the frame through a command queue of kCommandCapacity entries (applied at the start
/// of the next frame, in order); a go() that finds the queue full is refused and reported as a
/// warning (FaultReason::kQueueFull), never blocking and never overwriting.
///
/// Units: positions and speeds are in the output port's world units (its ratio converts them
/// into the generator's own state).
///
/// A reset of the output (BlockPort::reset or reset_deep) shifts the target with it, so a reset
/// never produces motion: an idle generator stays idle, a moving one keeps its remaining distance.
class PositionGenerator : public Block {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "PositionGenerator"; }
  PositionGenerator();

  /// go() commands that may wait for the next frame.
  static constexpr size_t kCommandCapacity = 8;

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
  /// Queued for the frame; returns kFull (and reports a warning) when kCommandCapacity commands
  /// are already waiting. Context: loop.
  Status go(double value, PositionMode mode, double speed_units_per_s);
  /// As go(value, mode, speed) with the speed in force then. Context: loop.
  Status go(double value, PositionMode mode);

  /// The target in world units once every queued go() has been applied (including the shift of
  /// a reset; a queued GLOBAL target counts as given). Context: loop.
  double target() const;
  /// True when no go() waits and the output sits on the target (a reset does not change this).
  /// Context: loop.
  bool is_idle() const;

  /// Publishes its names under "<instance_name>." in `registry`, an RPC, which lists them
  /// (docs/rpc.md): the same as registry->enroll(instance_name, *this). Context: loop (setup).
  template <class Registry>
  void enroll(Registry* registry, const char* instance_name) {
    registry->enroll(instance_name, *this);
  }
  /// One frame: apply the queued go() commands, step toward the target by at most
  /// speed × 40 µs, then set and push the output. Context: frame ISR.
  void run() override;

  /// The generated position (OUTPUT port; world units).
  BlockPort output;
  /// Travel speed in world units per second (written by set_speed, go, or an AnalogInput).
  ControlParameter speed_units_per_sec = 0;

 private:
  struct GoCommand {
    double value = 0.0;  // world units
    PositionMode mode = ABSOLUTE;
    bool set_speed = false;  // apply `speed` (world units/s) with the target
    double speed = 0.0;
  };

  Status queue(const GoCommand& command);
  void apply(const GoCommand& command);
  double max_step_block_units() const;
  void follow_output_reset();
  double frame_target_world() const;

  SpscQueue<GoCommand, kCommandCapacity> commands_;
  double queued_target_world_ = 0.0;  // loop only: the target after the last queued go()
  DecimalPosition position_ = 0;      // the output's state, block units
  DecimalPosition target_ = 0;        // block units
  DecimalPosition last_set_ = 0;      // position_ as this block last set it
  bool at_rest_ = false;              // a zero change was committed and pushed since the last move
};

}  // namespace stepdance
