// A potentiometer on a 10-bit ADC input: a schedule of knob positions.
#pragma once

#include <cstdint>
#include <vector>

#include "common/sim_time.hpp"

namespace stepdance::sim {

/// A pot whose wiper position (0..1) is set at scheduled times; the ADC reads round(position × 1023).
class Potentiometer {
 public:
  /// Full-scale 10-bit ADC reading.
  static constexpr uint16_t kAdcMax = 1023;

  /// A pot at `initial_position` (clamped to 0..1) from the start.
  explicit Potentiometer(double initial_position = 0.5);

  /// From `time` (ns) on, the wiper sits at `position` (clamped to 0..1). Later calls for the
  /// same time win.
  void set(SimTime time, double position);

  /// Wiper position (0..1) at `time`.
  double position_at(SimTime time) const;
  /// ADC reading (0..1023) at `time`: round(position × 1023), halves rounded up.
  uint16_t adc_value_at(SimTime time) const;

 private:
  struct Setting {
    SimTime time;
    double position;
  };
  double initial_position_;
  /// Settings sorted by time (stable).
  std::vector<Setting> settings_;
};

}  // namespace stepdance::sim
