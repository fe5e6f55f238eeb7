// The Harmonograph example's block graph on the manual host backend, for the frame benchmarks.
#pragma once

#include <math.h>
#include <stdint.h>

#include "hal_manual.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/core/engine.hpp"
#include "stepdance/core/fault.hpp"
#include "stepdance/io/analog_input.hpp"
#include "stepdance/io/button.hpp"
#include "stepdance/io/encoder.hpp"
#include "stepdance/io/output_port.hpp"
#include "stepdance/motion/channel.hpp"
#include "stepdance/motion/kinematics_core_xy.hpp"
#include "stepdance/motion/position_generator.hpp"
#include "stepdance/motion/scaling_filter.hpp"

namespace stepdance::workloads {

/// examples/Harmonograph without a sketch: two pendulum encoders → ScalingFilter2D (ratio from a
/// pot) → CoreXY → channels A/B; pen and two start generators; three output ports; a button.
class HarmonographGraph {
 public:
  HarmonographGraph() {
    hal_manual::reset();
    engine().clear();
    clear_fault();
    output_a.begin(OUTPUT_A);
    output_b.begin(OUTPUT_B);
    output_c.begin(OUTPUT_C);
    channel_a.begin(&output_a, SIGNAL_E);
    channel_a.set_ratio(25.4, 2032);
    channel_a.invert_output();
    channel_b.begin(&output_b, SIGNAL_E);
    channel_b.set_ratio(25.4, 2032);
    channel_b.invert_output();
    channel_z.begin(&output_c, SIGNAL_E);
    filter.begin();
    filter.output_1.map(&kinematics.input_x);
    filter.output_2.map(&kinematics.input_y);
    scale.begin(kDriverModuleV1.io_a[0]);
    scale.set_floor(0);
    scale.set_ceiling(20);
    scale.set_deadband(1, 509, 4);
    scale.map(&filter.ratio);
    hal_manual::set_adc(kDriverModuleV1.io_a[0], 1023);
    encoder_1.begin(ENCODER_1);
    encoder_1.set_ratio(24, 2400);
    encoder_1.invert();
    encoder_1.output.map(&filter.input_1);
    encoder_2.begin(ENCODER_2);
    encoder_2.set_ratio(24, 2400);
    encoder_2.invert();
    encoder_2.output.map(&filter.input_2);
    start_x.output.map(&kinematics.input_x);
    start_x.begin();
    start_y.output.map(&kinematics.input_y);
    start_y.begin();
    kinematics.begin();
    kinematics.output_a.map(&channel_a.input_target_position);
    kinematics.output_b.map(&channel_b.input_target_position);
    button.begin(kDriverModuleV1.io_d[0]);
    button.set_mode(BUTTON_MODE_TOGGLE);
    pen.output.map(&channel_z.input_target_position);
    pen.begin();
    dance_start();
    // The example carries the pen to its start first; the benchmark measures the drawing
    // afterwards, so the start generators begin there, at rest (a reset moves nothing).
    start_x.output.reset(-200);
    start_y.output.reset(-160);
    // Undamped swings of 266 counts (40° of a 2400-count turn) with 2 s and 2.02 s periods, by
    // rotating a unit vector once per frame (cheap; cos/sin only here).
    const double step_x = 2.0 * 3.14159265358979323846 * 40e-6 / 2.0;
    const double step_y = 2.0 * 3.14159265358979323846 * 40e-6 / 2.02;
    cos_x_ = cos(step_x);
    sin_x_ = sin(step_x);
    cos_y_ = cos(step_y);
    sin_y_ = sin(step_y);
  }

  /// Benchmark motion: both pendulums swinging at full amplitude (the busiest part of a
  /// harmonograph run), the pot at its end (ratio 20); the kilohertz tick every 25th frame (it
  /// reads the pot), then one frame runs.
  void run_busy_frame(uint32_t frame) {
    if (frame % 25 == 0) engine().run_kilohertz_tick();
    rotate(x_, vx_, cos_x_, sin_x_);
    rotate(y_, vy_, cos_y_, sin_y_);
    hal_manual::set_quadrature(0, static_cast<int32_t>(floor(266.67 * x_)));
    hal_manual::set_quadrature(1, static_cast<int32_t>(floor(266.67 * y_)));
    engine().run_frame();
  }

  OutputPort output_a, output_b, output_c;
  Channel channel_a, channel_b, channel_z;
  Encoder encoder_1, encoder_2;
  ScalingFilter2D filter;
  AnalogInput scale;
  KinematicsCoreXY kinematics;
  PositionGenerator pen, start_x, start_y;
  Button button;

 private:
  static void rotate(double& c, double& s, double cos_step, double sin_step) {
    const double next_c = c * cos_step - s * sin_step;
    s = s * cos_step + c * sin_step;
    c = next_c;
  }
  double x_ = 1, vx_ = 0, y_ = 0, vy_ = 1;  // y starts a quarter swing behind
  double cos_x_ = 1, sin_x_ = 0, cos_y_ = 1, sin_y_ = 0;
};

}  // namespace stepdance::workloads
