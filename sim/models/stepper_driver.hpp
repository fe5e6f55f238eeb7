// A TMC2209-like stepper driver with its motor: counts microsteps on STEP rising edges.
#pragma once

#include <cstdint>

#include "common/sim_time.hpp"

namespace stepdance::sim {

/// Settings of one driver socket and the motor on it.
struct StepperDriverSettings {
  /// Microsteps per full step, as set by the MS jumpers: 1, 2, 4, 8, 16, 32 or 64.
  int microsteps = 16;
  /// Full steps per motor revolution (200 for a 1.8° motor). Must be > 0.
  int full_steps_per_rev = 200;
  /// Whether the driver is enabled before the board first drives ENABLE.
  bool enabled = false;
  /// The motor is plugged in the other way round (one coil's pair swapped): it turns backwards
  /// for the same DIR level, so its position counts −1 per step with DIR high.
  bool reversed = false;
};

/// The driver and its motor. Position is counted in microsteps: +1 per STEP rising edge with DIR
/// high, −1 with DIR low (the other way round for a reversed motor). While disabled, steps do not move the motor and
/// are counted as ignored. ENABLE's active-low polarity is the board's concern; this model takes "enabled" directly.
class StepperDriver {
 public:
  explicit StepperDriver(const StepperDriverSettings& settings = {});

  /// True for the microstep settings a TMC2209 socket can be jumpered to (1..64, powers of two).
  static bool valid_microsteps(int microsteps);

  /// STEP rose at `time` (ns) with DIR at `dir_high`: moves one microstep if enabled.
  void on_step_rising(SimTime time, bool dir_high);
  /// Enables or disables the driver (true = ENABLE asserted).
  void set_enabled(bool enabled);
  bool enabled() const { return enabled_; }

  /// Changes the microstep setting; returns false and keeps the old one if it is not valid.
  /// Steps already taken keep the angle they turned the motor by.
  bool set_microsteps(int microsteps);
  int microsteps() const { return microsteps_; }
  int full_steps_per_rev() const { return full_steps_per_rev_; }
  /// Microsteps per revolution at the current setting.
  int64_t steps_per_rev() const { return int64_t{microsteps_} * full_steps_per_rev_; }

  /// Net position of the motor in microsteps: forward minus reverse steps taken while enabled,
  /// negated for a reversed motor.
  int64_t position_steps() const { return position_steps_; }
  bool reversed() const { return reversed_; }
  /// Motor rotation in revolutions since the start (each step counted at the setting it was taken at).
  double revolutions() const;
  /// Steps taken with DIR high / low while enabled (the driver's count, whichever way the motor
  /// is plugged in).
  uint64_t forward_steps() const { return forward_steps_; }
  uint64_t reverse_steps() const { return reverse_steps_; }
  /// Steps received while disabled (they did not move the motor).
  uint64_t ignored_steps() const { return ignored_steps_; }
  /// Time (ns) of the last step that moved the motor, or −1 if none has.
  SimTime last_step_time() const { return last_step_time_; }

 private:
  /// Finest microstep division: rotation is kept in 1/64 full steps, so it stays exact.
  static constexpr int kFinestMicrosteps = 64;

  int microsteps_;
  int full_steps_per_rev_;
  bool enabled_;
  bool reversed_;
  int64_t position_steps_ = 0;
  int64_t rotation_64ths_ = 0;
  uint64_t forward_steps_ = 0;
  uint64_t reverse_steps_ = 0;
  uint64_t ignored_steps_ = 0;
  SimTime last_step_time_ = -1;
};

}  // namespace stepdance::sim
