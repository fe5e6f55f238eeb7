// ScalingFilter: per-frame scaling of changes or positions.
#include "stepdance/motion/scaling_filter.hpp"

namespace stepdance {

template <int kChannels>
Status ScalingFilter<kChannels>::begin(PositionMode mode) {
  mode_ = mode == ABSOLUTE ? ABSOLUTE : INCREMENTAL;
  for (int i = 0; i < kChannels; ++i) {
    input_states_[i] = output_states_[i] = 0;
    inputs_[i]->begin(&input_states_[i], BLOCKPORT_INPUT, this);
    outputs_[i]->begin(&output_states_[i], BLOCKPORT_OUTPUT, this);
  }
  return register_in(Stage::kPreChannel);
}

// Frame context. INCREMENTAL scales each frame's change (a gear ratio), ABSOLUTE the position itself.
template <int kChannels>
void ScalingFilter<kChannels>::run() {
  for (int i = 0; i < kChannels; ++i) {
    inputs_[i]->pull();
    inputs_[i]->update();
    const double value = inputs_[i]->read(mode_) * ratio;
    outputs_[i]->set(outputs_[i]->convert_world_to_block_units(value), mode_);
    outputs_[i]->push();
  }
}

template class ScalingFilter<1>;
template class ScalingFilter<2>;

ScalingFilter1D::ScalingFilter1D() {
  inputs_[0] = &input;
  outputs_[0] = &output;
}

ScalingFilter2D::ScalingFilter2D() {
  inputs_[0] = &input_1;
  inputs_[1] = &input_2;
  outputs_[0] = &output_1;
  outputs_[1] = &output_2;
}

}  // namespace stepdance
