// WaveGenerator2D: a wave across the direction of travel, for decorating a moving pen.
#pragma once

#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/core/units.hpp"

namespace stepdance {

/// Sets (output_x, output_y) to an offset perpendicular to the travel direction `input_theta`
/// (rad): v = amplitude·sin θ, x = −v·sin(theta), y = v·cos(theta), absolute. With inputs,
/// θ = π·input_frequency·input_t (input_t usually a TimeBasedInterpolator's output_parameter,
/// 0 → 1 over a move, and input_frequency from MoveDurationToFrequency: a whole number of
/// half-waves per move, so every move starts and ends on the line). After setNoInput(),
/// θ advances by input_frequency × 40 µs per frame. The original used 3.1415 for π.
class WaveGenerator2D : public Block {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "WaveGenerator2D"; }
  Status begin();
  void setNoInput() { no_input_ = true; }
  void debugPrint() {}
  void run() override;

  BlockPort input_frequency;
  BlockPort input_t;
  BlockPort input_theta;
  BlockPort output_x;
  BlockPort output_y;
  /// Peak offset, output world units. Context: any.
  ControlParameter amplitude = 1.0f;

 private:
  bool no_input_ = false;
  double free_theta_ = 0.0;
  DecimalPosition frequency_ = 0;
  DecimalPosition t_ = 0;
  DecimalPosition theta_ = 0;
  DecimalPosition x_ = 0;
  DecimalPosition y_ = 0;
};

}  // namespace stepdance
