// HomingAxis: finds one axis's limit switch (fast seek, pull-off, slow approach, pull-off).
#pragma once

#include <stdint.h>

#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/core/units.hpp"
#include "stepdance/homing/switch_debouncer.hpp"

/// Homing directions (the original's values): toward increasing or decreasing positions.
constexpr float HOMING_DIR_FWD = 1.0f;
constexpr float HOMING_DIR_BWD = -1.0f;

/// Axis states (the original's numbers 0–5, then ours).
constexpr uint8_t HOMING_AXIS_STATE_BEGIN = 0;
constexpr uint8_t HOMING_AXIS_STATE_BACKING_OFF = 1;  ///< started on the switch: moving off it
constexpr uint8_t HOMING_AXIS_STATE_SEEKING = 2;      ///< fast toward the switch
constexpr uint8_t HOMING_AXIS_STATE_CENTERING = 3;    ///< the original's, never used
constexpr uint8_t HOMING_AXIS_STATE_FINISHED = 4;
constexpr uint8_t HOMING_AXIS_STATE_WAITING = 5;         ///< idle, or waiting for its turn
constexpr uint8_t HOMING_AXIS_STATE_PULLING_OFF = 6;     ///< after the fast hit, away by the pull-off
constexpr uint8_t HOMING_AXIS_STATE_APPROACHING = 7;     ///< slow toward the switch
constexpr uint8_t HOMING_AXIS_STATE_FINAL_PULL_OFF = 8;  ///< after the slow hit, away by the pull-off
constexpr uint8_t HOMING_AXIS_STATE_FAILED = 9;          ///< timed out or travelled too far

namespace stepdance {

/// Drives `output` (mapped INCREMENTAL to the axis's target port, world units) to find a limit
/// switch on `limit_pin`, in the frame (pre-channel stage), in this order:
///   1. if the switch is already pressed, back off it at the fast speed;
///   2. seek toward it at the fast speed (`velocity`);
///   3. pull off by the pull-off distance (and until the switch is released);
///   4. approach again at the slow speed: the trip point is where the switch closed;
///   5. pull off again, so the axis rests off the switch.
/// The switch is read every frame and debounced: a level counts once it has held for the
/// debounce time, and the trip point is the position where that level began, so bounce or a
/// glitch shorter than the debounce time never stops a move and the debounce adds no error.
/// A routine that takes longer than the timeout, or a seek or approach that travels farther
/// than the maximum travel, stops the axis and raises an alarm (FaultReason::kTimeout).
/// Nothing is printed from the frame. Homing (the sequencer) runs the axes; see homing.hpp.
class HomingAxis : public Block {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "HomingAxis"; }
  HomingAxis() = default;

  /// The axis's switch, the position the trip point gets, the direction toward the switch
  /// (HOMING_DIR_FWD/BWD), the fast speed (world units/s) and the target it moves. Context: loop.
  void configure(uint8_t limit_pin, double value_at_limit, float direction, float velocity, BlockPort* target);
  /// Sets the switch pin's pull-down (pull-up when active low), begins and maps the output and
  /// registers the block in the pre-channel stage. kNoSuchPin, kFull. Context: loop.
  Status begin();

  /// Slow approach speed, world units/s (default: a tenth of the fast speed). Context: loop.
  void set_slow_velocity(double units_per_s) { slow_velocity_ = units_per_s; }
  /// Distance of both pull-offs, world units (default 1). Context: loop.
  void set_pull_off_distance(double units) { pull_off_ = units; }
  /// How long a switch level must hold to count, ms (default 2). Context: loop.
  void set_debounce_ms(double ms);
  /// Longest the whole routine may take, ms (default 60 000; 0 = no limit). Context: loop.
  void set_timeout_ms(uint32_t ms) { timeout_ms_ = ms; }
  /// Farthest a seek or approach may travel before failing, world units (0 = no limit, the
  /// default). Context: loop.
  void set_max_travel(double units) { max_travel_ = units; }
  /// The switch reads active when its pin is low (a normally-closed switch to ground). Default:
  /// active high with a pull-down, as the original. Context: loop (before begin()).
  void set_active_low(bool active_low) { active_low_ = active_low; }

  /// Starts the routine from the top. Context: loop.
  void start();
  /// Stops the axis where it is (state WAITING). Context: loop.
  void abort();
  /// HOMING_AXIS_STATE_*. Context: any.
  uint8_t state() const { return state_; }
  /// Where (in the output's world units, since begin) the slow approach found the switch.
  /// Context: loop, once FINISHED.
  double trip_position() const { return trip_position_; }
  /// The output's position now, world units since begin. Context: loop.
  double position() const { return position_; }
  double value_at_limit() const { return value_at_limit_; }
  uint8_t limit_pin() const { return pin_; }
  BlockPort* target() const { return target_; }
  /// The debounced switch level. Context: any.
  bool switch_active() const { return switch_.level(); }

  /// One frame of the routine. Context: frame ISR.
  void run() override;

  /// The motion the routine makes (OUTPUT, world units), mapped to the target.
  BlockPort output;

 private:
  void run_state(bool hit, bool released);
  bool move(double velocity);
  bool pull_off_done(bool released);
  void enter(uint8_t state);
  void fail(const char* detail);
  bool read_switch() const;

  BlockPort* target_ = nullptr;
  double value_at_limit_ = 0;
  double direction_ = 1.0;
  double fast_velocity_ = 1.0;
  double slow_velocity_ = 0.0;  // 0: a tenth of the fast speed
  double pull_off_ = 1.0;
  double max_travel_ = 0.0;
  uint32_t timeout_ms_ = 60000u;
  uint32_t timeout_frames_ = 0;  // timeout_ms_ in frames of the period at start()
  double debounce_ms_ = 2.0;
  uint8_t pin_ = 255;
  bool active_low_ = false;

  SwitchDebouncer switch_;
  DecimalPosition position_ = 0;  // world units (the output's ratio is 1)
  double phase_start_ = 0;        // position where the current phase began
  double trip_position_ = 0;
  uint32_t frames_ = 0;  // since start()
  volatile uint8_t state_ = HOMING_AXIS_STATE_WAITING;
};

}  // namespace stepdance
