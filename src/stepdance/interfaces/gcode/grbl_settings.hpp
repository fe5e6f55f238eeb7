// Grbl 1.1's `$` settings ($0–$132): the values senders read with `$$` and write with `$N=v`.
#pragma once

#include <stdint.h>

#include "stepdance/interfaces/gcode/grbl_error.hpp"

namespace stepdance::gcode {

/// One setting's number, value and whether the host may change it.
struct GrblSetting {
  uint8_t number;
  double value;
  bool integer;                ///< printed without decimals; writes must be whole numbers
  bool writable;               ///< false: the sketch owns it (steps/mm come from the channels)
  double default_value = 0.0;  ///< Grbl's default or the sketch's (set_from_sketch); `$RST=$`
  bool host_set = false;       ///< written by the host (`$N=v`) or loaded from the store
  bool sketch_set = false;     ///< given by the sketch (set_from_sketch)
};

/// Every Grbl 1.1 setting, with Grbl's defaults where the value is the machine's business.
/// Context: loop only.
class GrblSettings {
 public:
  static constexpr int kCount = 34;

  GrblSettings();

  /// The setting with this number, or nullptr.
  const GrblSetting* find(uint32_t number) const;
  /// Value of a setting (0 for unknown numbers).
  double value(uint32_t number) const;
  /// `$N=value` from the host, by Grbl 1.1h's rules: kNegativeValue for negative values,
  /// kInvalidDollarStatement for unknown or read-only settings; integer settings keep the value
  /// truncated; kStepPulseTooShort for `$0` below 3 µs; kSoftLimitNeedsHoming for `$20` on while
  /// `$22` (homing) is off; `$22=0` also turns `$20` off.
  GrblError write(uint32_t number, double value);
  /// A value the host wrote earlier, read back from the store: only the setting's own range is
  /// checked (the order between settings, as `$20` after `$22`, held when it was written).
  GrblError load(uint32_t number, double value);
  /// Sets a value on behalf of the sketch (read-only ones included). False if unknown, or if the
  /// setting cannot hold it (negative, not finite, or above 255 for a whole-number setting).
  /// For a host-writable setting this is the default: a value the host wrote (and the board
  /// stored) wins over it, as a stored Grbl setting wins over the firmware's default.
  bool set_from_sketch(uint32_t number, double value);
  /// A read-only value the machine measures ($100–$102 from the channels at start): set as
  /// set_from_sketch() would, without counting as the sketch's own. False as set_from_sketch().
  bool set_from_machine(uint32_t number, double value);
  /// `$RST=$`: every setting back to its default (Grbl's or the sketch's).
  void restore_defaults();
  /// Settings in `$$` order.
  const GrblSetting& at(int index) const { return settings_[index]; }

  // Named readers for the settings the machine acts on.
  bool report_machine_position() const { return (static_cast<uint32_t>(value(10)) & 1u) != 0; }
  bool report_buffer_state() const { return (static_cast<uint32_t>(value(10)) & 2u) != 0; }
  bool report_inches() const { return value(13) != 0.0; }
  bool soft_limits() const { return value(20) != 0.0; }
  bool homing_enabled() const { return value(22) != 0.0; }
  double junction_deviation_mm() const { return value(11); }
  double arc_tolerance_mm() const { return value(12); }
  /// $110–$112 (axis 0–2), mm/min.
  double max_rate_mm_per_min(int axis) const { return value(110 + axis); }
  /// $120–$122 (axis 0–2), mm/s².
  double acceleration_mm_per_s2(int axis) const { return value(120 + axis); }
  /// $130–$132 (axis 0–2), mm.
  double max_travel_mm(int axis) const { return value(130 + axis); }

 private:
  GrblSetting* writable_setting(uint32_t number);

  GrblSetting settings_[kCount];
};

}  // namespace stepdance::gcode
