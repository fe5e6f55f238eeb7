// Attractor2D: pulls the machine toward a point, whatever else moves it.
#pragma once

#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/core/units.hpp"

namespace stepdance {

/// Each frame reads where the machine is through its outputs (deep reads: the position
/// downstream, knobs and all) and moves it toward the target by at most max_speed × 40 µs —
/// a spring without overshoot that other inputs can fight. Units: the outputs' world units.
/// Context: run() in the frame; setters from the loop.
class Attractor2D : public Block {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "Attractor2D"; }
  Status begin();
  /// INCREMENTAL: relative to where the machine is now; ABSOLUTE/GLOBAL: a position.
  /// max_speed in units/s. Context: loop.
  void set_target(double x, double y, PositionMode mode, double max_speed);
  void set_strength(double max_speed) { max_speed_ = max_speed; }
  void debugPrint() {}
  void run() override;

  BlockPort output_x;
  BlockPort output_y;

 private:
  volatile double target_x_ = 0.0;
  volatile double target_y_ = 0.0;
  volatile double max_speed_ = 0.0;
  DecimalPosition x_ = 0;
  DecimalPosition y_ = 0;
};

}  // namespace stepdance
