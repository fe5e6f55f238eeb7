// PathLengthGenerator: the path length of each frame's input changes.
#include "stepdance/motion/path_length_generator.hpp"

#include <math.h>

namespace stepdance {

template <int kInputs>
Status PathLengthGenerator<kInputs>::begin() {
  for (int i = 0; i < kInputs; ++i) {
    *input_states_[i] = 0;
    inputs_[i]->begin(input_states_[i], BLOCKPORT_INPUT, this);
  }
  output_state_ = 0;
  output_->begin(&output_state_, BLOCKPORT_OUTPUT, this);
  return register_in(Stage::kPreChannel);
}

// Frame context: output += ratio × √(Σ Δinput²), always ≥ 0 (e.g. extrusion that follows the XY path
// length whatever its direction; original-library.md §4.8).
template <int kInputs>
void PathLengthGenerator<kInputs>::run() {
  double sum_of_squares = 0.0;
  for (int i = 0; i < kInputs; ++i) {
    inputs_[i]->pull();
    inputs_[i]->update();
    const double change = inputs_[i]->read(INCREMENTAL);
    sum_of_squares += change * change;
  }
  const double length = sqrt(sum_of_squares) * ratio;
  output_->set(output_->convert_world_to_block_units(length), INCREMENTAL);
  output_->push();
}

template class PathLengthGenerator<2>;
template class PathLengthGenerator<3>;

PathLengthGenerator2D::PathLengthGenerator2D() {
  inputs_[0] = &input_1;
  inputs_[1] = &input_2;
  input_states_[0] = &input_1_position;
  input_states_[1] = &input_2_position;
  output_ = &output;
}

// ratio = output per revolution / circumference (2πr).
void PathLengthGenerator2D::set_ratio_for_circle(double radius, double output_per_revolution) {
  if (radius > 0.0) ratio = output_per_revolution / (2.0 * 3.14159265358979323846 * radius);
}

PathLengthGenerator3D::PathLengthGenerator3D() {
  inputs_[0] = &input_1;
  inputs_[1] = &input_2;
  inputs_[2] = &input_3;
  input_states_[0] = &input_1_position;
  input_states_[1] = &input_2_position;
  input_states_[2] = &input_3_position;
  output_ = &output;
}

}  // namespace stepdance
