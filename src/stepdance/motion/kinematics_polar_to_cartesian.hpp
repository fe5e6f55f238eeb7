// KinematicsPolarToCartesian (KinematicsLever): an angle and a radius become x and y.
#pragma once

#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/core/units.hpp"

namespace stepdance {

/// x = r·cos θ, y = r·sin θ (θ in radians, r and x/y in the ports' world units), set absolutely
/// every frame — e.g. a turntable's angle and an arm's reach, or a lever of fixed length.
/// Deep reads and pulls go back through the inverse map (θ = atan2(y, x), r = √(x² + y²)).
class KinematicsPolarToCartesian : public Block {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "KinematicsPolarToCartesian"; }
  /// Begins the ports and registers in the pre-channel stage. A fixed_radius > 0 sets the radius
  /// (an input mapped to input_radius still moves it). Context: loop.
  Status begin(double fixed_radius = 0.0);
  void reset() {}
  void run() override;
  void pull_deep() override;
  double read_deep(BlockPort& port) override;

  BlockPort input_radius;
  BlockPort input_angle;
  BlockPort output_x;
  BlockPort output_y;

 private:
  DecimalPosition radius_ = 0;
  DecimalPosition angle_ = 0;
  DecimalPosition x_ = 0;
  DecimalPosition y_ = 0;
};

/// The original library's other name for the same block.
using KinematicsLever = KinematicsPolarToCartesian;

}  // namespace stepdance
