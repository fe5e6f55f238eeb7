// PathLengthGenerator2D / 3D: an output that grows with the distance its inputs travel.
#pragma once

#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/core/units.hpp"

namespace stepdance {

/// Adds ratio × √(Σ Δinput²) to `output` every frame: e.g. extrusion in proportion to the XY
/// path a print head travels (never negative). Inputs and output in their ports' world units.
/// Context: run() in the frame; setters from the loop.
template <int kInputs>
class PathLengthGenerator : public Block {
 public:
  Status begin();
  /// Output units per unit of path. Context: loop.
  void set_ratio(double ratio_out_per_in) { ratio = ratio_out_per_in; }
  void set_ratio(double output_units, double input_units) {
    if (input_units != 0.0) ratio = output_units / input_units;
  }
  void run() override;

  /// Output units per unit of path length.
  volatile double ratio = 1.0;

 protected:
  BlockPort* inputs_[kInputs] = {};
  DecimalPosition* input_states_[kInputs] = {};
  BlockPort* output_ = nullptr;
  DecimalPosition output_state_ = 0;
};

/// Two inputs (an XY path).
class PathLengthGenerator2D : public PathLengthGenerator<2> {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "PathLengthGenerator2D"; }
  PathLengthGenerator2D();
  /// ratio = output_per_revolution / (2π·radius): the output per turn of a circle of `radius`.
  void set_ratio_for_circle(double radius, double output_per_revolution);
  using PathLengthGenerator<2>::set_ratio;

  BlockPort input_1;
  BlockPort input_2;
  BlockPort output;
  /// The inputs' states (block units), public as in the original.
  DecimalPosition input_1_position = 0;
  DecimalPosition input_2_position = 0;
};

/// Three inputs (an XYZ path).
class PathLengthGenerator3D : public PathLengthGenerator<3> {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "PathLengthGenerator3D"; }
  PathLengthGenerator3D();
  using PathLengthGenerator<3>::set_ratio;

  BlockPort input_1;
  BlockPort input_2;
  BlockPort input_3;
  BlockPort output;
  DecimalPosition input_1_position = 0;
  DecimalPosition input_2_position = 0;
  DecimalPosition input_3_position = 0;
};

}  // namespace stepdance
