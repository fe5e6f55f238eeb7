// The hobby-servo driver board (ATtiny84 firmware) as a model: STEP/DIR in, one pulse per period out.
#pragma once

#include <cstdint>
#include <vector>

#include "common/sim_time.hpp"
#include "servo_pulse.h"

namespace stepdance::sim {

/// The two firmware builds: ±500 steps (90°) and ±750 steps (180°).
enum class ServoBuild { k90deg, k180deg };

/// The firmware's settings for a build: period 24 000 + 850 µs, neutral 1500 + 40 µs and the
/// build's step window.
servo_pulse_settings servo_build_settings(ServoBuild build);

/// The servo board, using the firmware's own arithmetic (servo_pulse.h):
///   - counting: ±1 per STEP rising edge with the DIR level at that edge; never saturates;
///   - pulse k (k = 0, 1, …) starts at power_up + k × period and is high for its width;
///   - pulses 0 and 1 have the neutral width; pulse k ≥ 2 has width(position sampled at
///     power_up + (k − 1) × period + sample_delay), the moment the main loop reads the position
///     after TOV1. A step exactly at a sample instant is not in that sample.
/// Times must not go backwards between calls that change state (on_step_rising, advance_to);
/// queries of earlier times are answered from the recorded widths.
class ServoBoard {
 public:
  /// Delay from a pulse start to the firmware's position sample (docs/servo-driver.md: ~3.5 µs).
  static constexpr SimTime kDefaultSampleDelay = 3500 * kNanosecond;

  /// A board running the given build, powered up at `power_up` (ns).
  explicit ServoBoard(ServoBuild build = ServoBuild::k90deg, SimTime power_up = 0);
  /// A board with custom settings. Check settings_valid(): invalid settings give meaningless widths.
  ServoBoard(const servo_pulse_settings& settings, SimTime power_up, SimTime sample_delay);

  /// True when the settings pass servo_pulse_settings_valid() and the sample delay lies in the period.
  bool settings_valid() const;
  const servo_pulse_settings& settings() const { return settings_; }

  /// STEP rose at `time` (ns) with DIR at `dir_high`. Steps before power-up are ignored.
  void on_step_rising(SimTime time, bool dir_high);
  /// Takes every position sample due at or before `time`.
  void advance_to(SimTime time);

  /// Step position (unclamped).
  int32_t position_steps() const { return position_steps_; }
  /// Steps that arrived before power-up (ignored).
  uint64_t steps_before_power_up() const { return steps_before_power_up_; }

  /// Width in µs of the pulse period in progress at `time` (0 before power-up). Advances to `time`.
  uint16_t pulse_width_us_at(SimTime time);
  /// Level of the servo output at `time`. Advances to `time`.
  bool output_high_at(SimTime time);

  /// Index of the pulse period in progress at `time`, or −1 before power-up.
  int64_t pulse_index_at(SimTime time) const;
  /// Start time (ns) of pulse `index`.
  SimTime pulse_start(int64_t index) const { return power_up_ + index * period_; }
  /// Pulse period in ns (24 850 µs for both builds).
  SimTime period() const { return period_; }
  /// Width in µs at zero steps (1540 µs for both builds).
  uint16_t neutral_width_us() const;

 private:
  SimTime sample_time(int64_t sample_index) const { return pulse_start(sample_index) + sample_delay_; }

  servo_pulse_settings settings_;
  SimTime power_up_;
  SimTime sample_delay_;
  SimTime period_;
  int32_t position_steps_ = 0;
  uint64_t steps_before_power_up_ = 0;
  /// Next sample to take; sample j (j ≥ 1) sets the width of pulse j + 1.
  int64_t next_sample_ = 1;
  /// Width of pulse k + 2 at index k.
  std::vector<uint16_t> sampled_widths_;
};

}  // namespace stepdance::sim
