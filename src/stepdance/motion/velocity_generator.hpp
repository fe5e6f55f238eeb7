// VelocityGenerator: an output that moves at a set speed, forever.
#pragma once

#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/core/units.hpp"
#include "stepdance/motion/rate_ramp.hpp"

namespace stepdance {

/// Adds speed_units_per_sec × 40 µs to `output` every frame (world units of the output's ratio).
/// A knob mapped to speed_units_per_sec makes a jog wheel that keeps going. With
/// set_acceleration() the speed ramps to a new setting instead of jumping (off by default).
class VelocityGenerator : public Block {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "VelocityGenerator"; }
  /// Begins the output and registers in the pre-channel stage. kFull if full. Context: loop.
  Status begin();
  /// One frame: output += speed × 40 µs, pushed. Context: frame ISR.
  void run() override;
  /// Limits how fast the speed changes, output world units per second²; 0 (default) = no limit.
  /// Context: any.
  void set_acceleration(double units_per_s2) { ramp_.set_limit(units_per_s2); }
  /// The speed used in the last frame (world units/s). Context: any.
  double current_speed() const { return ramp_.current(); }

  BlockPort output;
  /// Speed, output world units per second. Context: any.
  ControlParameter speed_units_per_sec = 0;

 private:
  DecimalPosition position_ = 0;
  RateRamp ramp_;
};

}  // namespace stepdance
