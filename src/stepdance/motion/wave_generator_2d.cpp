// WaveGenerator2D: the perpendicular offset, set absolutely each frame.
#include "stepdance/motion/wave_generator_2d.hpp"

#include <math.h>

namespace stepdance {

namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

Status WaveGenerator2D::begin() {
  frequency_ = t_ = theta_ = x_ = y_ = 0;
  free_theta_ = 0.0;
  input_frequency.begin(&frequency_, BLOCKPORT_INPUT, this);
  input_t.begin(&t_, BLOCKPORT_INPUT, this);
  input_theta.begin(&theta_, BLOCKPORT_INPUT, this);
  output_x.begin(&x_, BLOCKPORT_OUTPUT, this);
  output_y.begin(&y_, BLOCKPORT_OUTPUT, this);
  return register_in(Stage::kPreChannel);
}

// Frame context. An offset perpendicular to the travel direction input_theta: (−v sin θd, v cos θd)
// with v = amplitude·sin θ, set absolutely. θ = π·f·t with t the interpolator's 0→1 progress, so a
// move holds f half-waves (with MoveDurationToFrequency, a whole number), or advances by time without
// an input. π is exact here; the original used 3.1415 (original-library.md §4.8).
void WaveGenerator2D::run() {
  BlockPort* inputs[3] = {&input_frequency, &input_t, &input_theta};
  for (BlockPort* port : inputs) {
    port->pull();
    port->update();
  }
  const double frequency = input_frequency.read(ABSOLUTE);
  double theta;
  if (no_input_) {
    free_theta_ = fmod(free_theta_ + frequency * frame_period_s(), 2.0 * kPi);
    theta = free_theta_;
  } else {
    theta = kPi * frequency * input_t.read(ABSOLUTE);
  }
  const double v = static_cast<double>(amplitude) * sin(theta);
  const double direction = input_theta.read(ABSOLUTE);
  output_x.set(output_x.convert_world_to_block_units(-v * sin(direction)), ABSOLUTE);
  output_y.set(output_y.convert_world_to_block_units(v * cos(direction)), ABSOLUTE);
  output_x.push();
  output_y.push();
}

}  // namespace stepdance
