// WaveGenerator1D: increments from the closed-form wave.
#include "stepdance/motion/wave_generator_1d.hpp"

#include <math.h>

namespace stepdance {

Status WaveGenerator1D::begin() {
  input_state_ = output_state_ = 0;
  angle_.reset();
  input.begin(&input_state_, BLOCKPORT_INPUT, this);
  output.begin(&output_state_, BLOCKPORT_OUTPUT, this);
  return register_in(Stage::kPreChannel);
}

// Frame context. The output is the difference of the closed form amplitude·sin(θ + phase) between two
// frames, so it never drifts, unlike the original's integrated cos θ·dθ increments; phase is a real
// phase here (the original added it to the amplitude, original-library.md §4.8). With an input, θ
// advances by frequency × input change (a spatial wave along a path); without, by time.
void WaveGenerator1D::run() {
  input.pull();
  input.update();
  const double before = angle_.angle();
  // The angle source wraps into [0, 2π); the sines do not care.
  const double after = angle_.advance(frequency, !no_input_, input);
  const double phi = phase;
  const double from = trig_.sine(before + phi);  // where the last frame ended: remembered
  const double change = static_cast<double>(amplitude) * (trig_.sine(after + phi) - from);
  output.set(output.convert_world_to_block_units(change), INCREMENTAL);
  output.push();
}

}  // namespace stepdance
