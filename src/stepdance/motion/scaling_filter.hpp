// ScalingFilter1D / 2D: outputs that follow inputs times a ratio.
#pragma once

#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/core/units.hpp"

namespace stepdance {

/// INCREMENTAL (default): each output change is its input's change × ratio (the output keeps
/// its own offset). ABSOLUTE: each output is its input's position × ratio. One ratio for all
/// channels. Context: run() in the frame; setters from the loop.
template <int kChannels>
class ScalingFilter : public Block {
 public:
  Status begin(PositionMode mode = INCREMENTAL);
  void set_ratio(double output_per_input) { ratio = output_per_input; }
  void set_ratio(double output_units, double input_units) {
    if (input_units != 0.0) ratio = output_units / input_units;
  }
  void run() override;

  /// Output units per input unit.
  volatile double ratio = 1.0;

 protected:
  BlockPort* inputs_[kChannels] = {};
  BlockPort* outputs_[kChannels] = {};
  DecimalPosition input_states_[kChannels] = {};
  DecimalPosition output_states_[kChannels] = {};
  PositionMode mode_ = INCREMENTAL;
};

class ScalingFilter1D : public ScalingFilter<1> {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "ScalingFilter1D"; }
  ScalingFilter1D();
  BlockPort input;
  BlockPort output;
};

class ScalingFilter2D : public ScalingFilter<2> {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "ScalingFilter2D"; }
  ScalingFilter2D();
  BlockPort input_1;
  BlockPort input_2;
  BlockPort output_1;
  BlockPort output_2;
};

}  // namespace stepdance
