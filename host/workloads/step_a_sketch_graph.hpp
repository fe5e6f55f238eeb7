// A Step-A-Sketch-sized block graph on the manual host backend, shared by the demo and benchmarks.
#pragma once

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
#include "stepdance/motion/position_generator.hpp"

namespace stepdance::workloads {

/// Two encoders → CoreXY → channels A/B, a position generator → channel C (pen), three output
/// ports and a toggle button: the graph of the Step-A-Sketch example, built without a sketch.
class StepASketchGraph {
 public:
  StepASketchGraph() {
    hal_manual::reset();
    engine().clear();
    clear_fault();
    output_a.begin(OUTPUT_A);
    output_b.begin(OUTPUT_B);
    output_c.begin(OUTPUT_C);
    channel_a.begin(&output_a, SIGNAL_E);
    channel_b.begin(&output_b, SIGNAL_E);
    channel_z.begin(&output_c, SIGNAL_E);
    channel_a.set_ratio(25.4, 2032);
    channel_b.set_ratio(25.4, 2032);
    channel_a.invert_output();
    channel_b.invert_output();
    encoder_1.begin(ENCODER_1);
    encoder_2.begin(ENCODER_2);
    encoder_1.set_ratio(24, 2400);
    encoder_2.set_ratio(24, 2400);
    encoder_1.output.map(&kinematics.input_x);
    encoder_2.output.map(&kinematics.input_y);
    kinematics.begin();
    kinematics.output_a.map(&channel_a.input_target_position);
    kinematics.output_b.map(&channel_b.input_target_position);
    pen.output.map(&channel_z.input_target_position);
    pen.begin();
    button.begin(kDriverModuleV1.io_d[0]);
    button.set_mode(BUTTON_MODE_TOGGLE);
    dance_start();
  }

  /// Benchmark motion: both knobs turn steadily (X at 8333 counts/s, Y at 5000 counts/s, i.e.
  /// 83 and 50 mm/s) and the pen moves every two seconds; then one frame runs.
  void run_busy_frame(uint32_t frame) {
    hal_manual::set_quadrature(0, static_cast<int32_t>(frame / 3));
    hal_manual::set_quadrature(1, static_cast<int32_t>(frame / 5));
    if (frame % 50000 == 0) pen.go((frame / 50000) % 2 ? 200.0 : -200.0, ABSOLUTE, 2000);
    engine().run_frame();
  }

  OutputPort output_a, output_b, output_c;
  Channel channel_a, channel_b, channel_z;
  Encoder encoder_1, encoder_2;
  KinematicsCoreXY kinematics;
  PositionGenerator pen;
  Button button;
};

}  // namespace stepdance::workloads
