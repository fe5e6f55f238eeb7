// The ClayTexturizer example's block graph on the manual host backend, for the frame benchmarks.
#pragma once

#include <stdint.h>

#include "hal_manual.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/core/engine.hpp"
#include "stepdance/core/fault.hpp"
#include "stepdance/io/analog_input.hpp"
#include "stepdance/io/encoder.hpp"
#include "stepdance/io/output_port.hpp"
#include "stepdance/motion/channel.hpp"
#include "stepdance/motion/kinematics_polar_to_cartesian.hpp"
#include "stepdance/motion/path_length_generator.hpp"
#include "stepdance/motion/position_generator.hpp"
#include "stepdance/motion/scaling_filter.hpp"
#include "stepdance/motion/velocity_generator.hpp"
#include "stepdance/motion/wave_generator_1d.hpp"

namespace stepdance::workloads {

/// examples/ClayTexturizer without a sketch: pedal → VelocityGenerator → polar angle; lever →
/// radius; a WaveGenerator1D on the radius; z per turn; path-length extrusion; four channels and
/// output ports; two centre generators; three pots.
class ClayTexturizerGraph {
 public:
  ClayTexturizerGraph() {
    hal_manual::reset();
    engine().clear();
    clear_fault();
    output_a.begin(OUTPUT_A);
    output_b.begin(OUTPUT_B);
    output_c.begin(OUTPUT_C);
    output_d.begin(OUTPUT_D);
    channel_x.begin(&output_a, SIGNAL_E);
    channel_x.set_ratio(1, 80);
    channel_y.begin(&output_b, SIGNAL_E);
    channel_y.set_ratio(1, 80);
    channel_z.begin(&output_c, SIGNAL_E);
    channel_z.set_ratio(1, 400);
    channel_e.begin(&output_d, SIGNAL_E);
    channel_e.set_ratio(1, 93);
    turn_speed.begin();
    turn_speed.output.map(&polar.input_angle);
    lever.begin(ENCODER_1);
    lever.set_ratio(24, 2400);
    lever.output.map(&polar.input_radius);
    wave.input.map(&polar.input_angle, INCREMENTAL);
    wave.output.map(&polar.input_radius);
    wave.begin();
    polar.output_x.map(&channel_x.input_target_position);
    polar.output_y.map(&channel_y.input_target_position);
    polar.begin();
    z_per_turn.begin();
    z_per_turn.set_ratio(2.0, 6.283185307179586);
    z_per_turn.input.map(&polar.input_angle);
    z_per_turn.output.map(&channel_z.input_target_position);
    clay.begin();
    clay.set_ratio(0.05);
    clay.input_1.map(&polar.output_x);
    clay.input_2.map(&polar.output_y);
    clay.output.map(&channel_e.input_target_position);
    centre_x.output.map(&channel_x.input_target_position);
    centre_x.begin();
    centre_y.output.map(&channel_y.input_target_position);
    centre_y.begin();
    pedal.set_floor(0, 25);
    pedal.set_ceiling(2.75, 1020);
    pedal.map(&turn_speed.speed_units_per_sec);
    pedal.begin(kDriverModuleV1.io_a[0]);
    wave_height.set_floor(0, 0);
    wave_height.set_ceiling(4, 1023);
    wave_height.map(&wave.amplitude);
    wave_height.begin(kDriverModuleV1.io_a[1]);
    wave_count.set_floor(0, 0);
    wave_count.set_ceiling(16, 1023);
    wave_count.map(&wave.frequency);
    wave_count.begin(kDriverModuleV1.io_a[3]);
    hal_manual::set_adc(kDriverModuleV1.io_a[0], 1023);  // pedal down: 2.75 rad/s
    hal_manual::set_adc(kDriverModuleV1.io_a[1], 767);   // a 3 mm wave
    hal_manual::set_adc(kDriverModuleV1.io_a[3], 512);   // 8 waves a turn
    hal_manual::set_quadrature(0, 4000);                 // the lever out at 40 mm
    dance_start();
    // The example carries the nozzle to the bed's centre first; the benchmark measures the wall
    // being printed afterwards, so its centre generators start there, at rest (a reset moves
    // nothing).
    centre_x.output.reset(110);
    centre_y.output.reset(110);
  }

  /// Benchmark motion: printing the textured wall (pedal down, wave on, every block busy); the
  /// kilohertz tick every 25th frame (it reads the pots), then one frame runs.
  void run_busy_frame(uint32_t frame) {
    if (frame % 25 == 0) engine().run_kilohertz_tick();
    engine().run_frame();
  }

  OutputPort output_a, output_b, output_c, output_d;
  Channel channel_x, channel_y, channel_z, channel_e;
  KinematicsPolarToCartesian polar;
  AnalogInput pedal, wave_height, wave_count;
  Encoder lever;
  VelocityGenerator turn_speed;
  ScalingFilter1D z_per_turn;
  PathLengthGenerator2D clay;
  WaveGenerator1D wave;
  PositionGenerator centre_x, centre_y;
};

}  // namespace stepdance::workloads
