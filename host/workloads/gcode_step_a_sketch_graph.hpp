// The Step-A-Sketch graph with a GCodeInterface streaming a drawing into it: the GCodeStepASketch
// example's "G-code while moving" (knobs and a G-code sender summed at the kinematics), for the
// frame benchmarks.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "gcode_workload.hpp"
#include "step_a_sketch_graph.hpp"
#include "stepdance/core/byte_stream.hpp"
#include "stepdance/interfaces/gcode/gcode_interface.hpp"

namespace stepdance::workloads {

/// A sender that never runs dry: LoopingProgram's lines ("G21 G90 G1 F3000", then a 180-gon of
/// 0.2 mm sides, round and round), one after another. The link's receive buffer applies the
/// back-pressure a real serial port would. Replies vanish. Context: loop.
class EndlessGcodeSender final : public ByteStream {
 public:
  size_t bytes_available() override {
    if (program_.bytes_available() == 0) program_.next_line();
    return program_.bytes_available();
  }
  int read_byte() override { return bytes_available() > 0 ? program_.read_byte() : -1; }
  size_t write_bytes(const uint8_t*, size_t length) override { return length; }
  size_t write_space() override { return 4096; }

 private:
  LoopingProgram program_;
};

/// StepASketchGraph, plus a GCodeInterface whose x and y feed the same CoreXY kinematics as the
/// knobs, with the GCodeStepASketch example's rates and accelerations. Its planner runs in the
/// frame; the link (parsing, planning) runs in the loop, outside the measured frame.
class GcodeStepASketchGraph : public StepASketchGraph {
 public:
  GcodeStepASketchGraph() {
    gcode.begin(&sender);
    gcode.output_x.map(&kinematics.input_x);
    gcode.output_y.map(&kinematics.input_y);
    gcode.settings().set_from_sketch(110, 6000);  // mm/min
    gcode.settings().set_from_sketch(111, 6000);
    gcode.settings().set_from_sketch(120, 2000);  // mm/s²
    gcode.settings().set_from_sketch(121, 2000);
    for (int pass = 0; pass < 8; ++pass) engine().run_loop();  // the queue fills before frame 0
  }

  /// The knobs turn and the pen moves as in StepASketchGraph; every 25th frame (each ms) the
  /// loop serves the link (outside the frame); then one frame runs.
  void run_busy_frame(uint32_t frame) {
    if (frame % 25 == 0) engine().run_loop();
    StepASketchGraph::run_busy_frame(frame);
  }

  EndlessGcodeSender sender;
  GCodeInterface gcode;
};

}  // namespace stepdance::workloads
