// Homing: runs the HomingAxis routines of up to five axes, in order or together.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/fixed_list.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/homing/homing_axis.hpp"

namespace stepdance {

/// Homes a machine against its limit switches (original API: add_axis, begin,
/// start_homing_routine). Each axis runs HomingAxis's routine (fast seek, pull-off, slow
/// approach, pull-off) in the frame; this block sequences them from the loop:
///  - axes run one after another in add_axis() order (default) or all together;
///  - while an axis runs, every other port that pushes into its target (knobs, planners, other
///    generators) is gated off, so nothing else moves the axis; their changes meanwhile are
///    dropped, and the gates are restored when homing ends;
///  - when every axis has finished, each target is reset through the chain (reset_deep,
///    no motion) so the trip point reads value_at_limit (the axis rests a pull-off away);
///  - the completion callback runs from dance_loop(); status is readable any time.
/// An axis that times out or travels too far raises an alarm; homing then stops every axis and
/// calls the failure callback. Unlike the original, axes may be added after begin().
class Homing : public Block {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "Homing"; }
  /// A user callback, run from dance_loop().
  using Callback = void (*)();
  /// Axes one Homing can run (the original's MAX_NUM_AXES).
  static constexpr size_t kMaxAxes = 5;
  /// Other ports it can gate off while homing.
  static constexpr size_t kMaxHeldPorts = 16;

  Homing() = default;

  /// Adds an axis: switch pin, the position the trip point gets, the direction toward the
  /// switch (HOMING_DIR_FWD/BWD), the fast speed (world units/s) and the target port to move.
  /// kFull beyond kMaxAxes, kBadArgument for a null target. Context: loop.
  Status add_axis(uint8_t limit_pin, double value_at_limit, float direction, float velocity, BlockPort* target);
  /// Begins every axis and registers the sequencer in the loop stage. Context: loop.
  Status begin();
  /// Starts homing every axis (restarts a routine under way). Context: loop.
  void start_homing_routine();
  /// Stops every axis where it is and restores the other sources. Context: loop.
  void abort();
  /// Home all axes at once instead of one after another. Context: loop.
  void set_home_together(bool together) { together_ = together; }
  /// Called once when every axis has homed / when homing failed. Context: loop.
  void set_callback_on_finished(Callback callback) { on_finished_ = callback; }
  void set_callback_on_failed(Callback callback) { on_failed_ = callback; }

  /// True while a routine runs. Context: loop.
  bool is_homing() const { return running_; }
  /// True once every axis has homed (until the next start). Context: loop.
  bool is_homed() const { return homed_; }
  /// True if the last routine failed (timeout, travel, a fatal fault). Context: loop.
  bool has_failed() const { return failed_; }
  /// Axis i (in add_axis order), to tune its speeds, pull-off, debounce, timeout and travel.
  HomingAxis& axis(size_t index) { return axes_[index]; }
  size_t axis_count() const { return axis_count_; }
  /// True while a routine runs and one of its axes watches `pin`. Context: any.
  bool owns_switch(uint8_t pin) const;
  /// Ports gated off while homing that did not fit kMaxHeldPorts (they kept moving). Context: loop.
  uint32_t ports_not_held() const { return ports_not_held_; }

  /// Sequences the axes and delivers the callbacks. Context: loop.
  void loop() override;

 private:
  void start_axis(HomingAxis& axis);
  void hold_other_sources(const HomingAxis& axis);
  void release_sources();
  void finish();
  void fail();
  bool all_axes(uint8_t state) const;

  HomingAxis axes_[kMaxAxes];
  size_t axis_count_ = 0;
  size_t current_ = 0;
  FixedList<BlockPort*, kMaxHeldPorts> held_;
  uint32_t ports_not_held_ = 0;
  Callback on_finished_ = nullptr;
  Callback on_failed_ = nullptr;
  bool begun_ = false;
  bool together_ = false;
  bool running_ = false;
  bool homed_ = false;
  bool failed_ = false;
};

}  // namespace stepdance
