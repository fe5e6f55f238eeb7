// The Pantograph example's block graph on the manual host backend, for the frame benchmarks.
#pragma once

#include <math.h>
#include <stdint.h>

#include "hal_manual.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/core/engine.hpp"
#include "stepdance/core/fault.hpp"
#include "stepdance/io/button.hpp"
#include "stepdance/io/encoder.hpp"
#include "stepdance/io/output_port.hpp"
#include "stepdance/motion/channel.hpp"
#include "stepdance/motion/kinematics_core_xy.hpp"
#include "stepdance/motion/kinematics_five_bar.hpp"
#include "stepdance/motion/position_generator.hpp"

namespace stepdance::workloads {

/// examples/Pantograph without a sketch: two 40,000-count joint encoders → KinematicsFiveBarForward
/// → CoreXY (plus two shift generators) → channels A/B; a pen generator → channel C; three output
/// ports and a toggle button.
class PantographGraph {
 public:
  PantographGraph() {
    hal_manual::reset();
    engine().clear();
    clear_fault();
    output_a.begin(OUTPUT_A);
    output_b.begin(OUTPUT_B);
    output_c.begin(OUTPUT_C);
    channel_a.begin(&output_a, SIGNAL_E);
    channel_a.set_ratio(1, 80);
    channel_b.begin(&output_b, SIGNAL_E);
    channel_b.set_ratio(1, 80);
    channel_z.begin(&output_c, SIGNAL_E);
    // The benchmark measures the drawing, not the arm's first jump from its stops (the example
    // starts at −60° and 240°) to the circle: the joints start on the circle, and after the
    // start everything downstream is set there at rest.
    double right_rad = 0, left_rad = 0;
    joints_at(0, right_rad, left_rad);
    encoder_r.begin(ENCODER_1);
    encoder_r.set_ratio(kTwoPi, kCountsPerTurn);
    encoder_r.set(right_rad);
    encoder_r.output.map(&five_bar.input_r, ABSOLUTE);
    encoder_l.begin(ENCODER_2);
    encoder_l.set_ratio(kTwoPi, kCountsPerTurn);
    encoder_l.set(left_rad);
    encoder_l.output.map(&five_bar.input_l, ABSOLUTE);
    five_bar.begin(60, 145.75f, 134, 169, 178.3f, 28.82f, 2.9019f);  // the example's arm (mm, rad)
    five_bar.output_x.map(&core_xy.input_x);
    five_bar.output_y.map(&core_xy.input_y);
    shift_x.output.map(&core_xy.input_x);
    shift_x.begin();
    shift_y.output.map(&core_xy.input_y);
    shift_y.begin();
    core_xy.begin();
    core_xy.output_a.map(&channel_a.input_target_position);
    core_xy.output_b.map(&channel_b.input_target_position);
    button.begin(kDriverModuleV1.io_d[0]);
    button.set_mode(BUTTON_MODE_TOGGLE);
    pen.output.map(&channel_z.input_target_position);
    pen.begin();
    dance_start();
    engine().run_frame();                                       // the five-bar finds the stylus's first pose
    core_xy.input_x.push_deep(core_xy.input_x.read(ABSOLUTE));  // the channels take it, at rest
  }

  /// Benchmark motion: both joints swing 0.1 rad about a pose that puts the stylus 160 mm out
  /// from the pivots, a quarter period apart with a 4 s period, so the stylus loops at 12–60 mm/s
  /// (37.5 mm/s on average; the example draws at 25 mm/s) and both encoders count every frame.
  void run_busy_frame(uint32_t frame) {
    double right_rad = 0, left_rad = 0;
    joints_at(frame, right_rad, left_rad);
    engine().run_frame();
  }

  OutputPort output_a, output_b, output_c;
  Channel channel_a, channel_b, channel_z;
  KinematicsFiveBarForward five_bar;
  KinematicsCoreXY core_xy;
  Encoder encoder_r, encoder_l;
  Button button;
  PositionGenerator pen, shift_x, shift_y;

 private:
  static constexpr double kTwoPi = 6.283185307179586;
  static constexpr double kCountsPerTurn = 40000;
  // FiveBarGeometry{60, 145.75, 134, 169, 178.3, 28.82, 2.9019}.inverse(0, 160): the example's
  // arm with its stylus 160 mm out on the centre line.
  static constexpr double kRightCentreRad = 0.373780;
  static constexpr double kLeftCentreRad = -0.138095;

  static int32_t counts(double joint_rad) { return static_cast<int32_t>(lround(joint_rad * kCountsPerTurn / kTwoPi)); }

  // The joints' angles at `frame`, also set as the encoders' counts.
  static void joints_at(uint32_t frame, double& right_rad, double& left_rad) {
    const double phase = kTwoPi * frame * 40e-6 / 4.0;
    right_rad = kRightCentreRad + 0.1 * sin(phase);
    left_rad = kLeftCentreRad + 0.1 * cos(phase);
    hal_manual::set_quadrature(0, counts(right_rad));  // Encoder::set() keeps count = angle / ratio
    hal_manual::set_quadrature(1, counts(left_rad));
  }
};

}  // namespace stepdance::workloads
