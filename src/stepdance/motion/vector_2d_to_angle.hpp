// Vector2DToAngle and MoveDurationToFrequency: small converters for wave decoration.
#pragma once

#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/core/units.hpp"

namespace stepdance {

/// output_theta = atan2(Δy, Δx) of the inputs' change each frame, radians: the direction of
/// travel. While the inputs stand still it keeps the last direction (the original fell back to 0,
/// which swung a wave decoration round at every stop).
class Vector2DToAngle : public Block {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "Vector2DToAngle"; }
  Status begin();
  void run() override;

  BlockPort input_x;
  BlockPort input_y;
  BlockPort output_theta;

 private:
  DecimalPosition x_ = 0;
  DecimalPosition y_ = 0;
  DecimalPosition theta_ = 0;
};

/// output_frequency = round(move duration × target_frequency), at least 1: a whole number of
/// half-waves in every move for WaveGenerator2D (so each move begins and ends on its line).
/// A duration of 0 or less gives target_frequency itself.
class MoveDurationToFrequency : public Block {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "MoveDurationToFrequency"; }
  Status begin();
  void run() override;

  BlockPort input_move_duration;
  BlockPort output_frequency;
  /// Half-waves per second of move. Context: any.
  ControlParameter target_frequency = 1.0f;

 private:
  DecimalPosition duration_ = 0;
  DecimalPosition frequency_ = 0;
};

}  // namespace stepdance
