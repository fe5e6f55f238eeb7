// The Step-A-Sketch graph with a TimeBasedInterpolator drawing into it: knobs and planned motion
// mixed, for the frame benchmarks (the planner issue's "Step-A-Sketch + TBI while moving").
#pragma once

#include <stdint.h>

#include "step_a_sketch_graph.hpp"
#include "stepdance/motion/time_based_interpolator.hpp"

namespace stepdance::workloads {

/// StepASketchGraph, plus a TBI whose x and y feed the same CoreXY kinematics as the knobs. The
/// host keeps its queue topped up with a zig-zag of 2 mm segments at 50 mm/s (a 90° corner at
/// every vertex, so the planner's look-ahead and the trapezoids are always at work).
class StepASketchTbiGraph : public StepASketchGraph {
 public:
  StepASketchTbiGraph() {
    tbi.begin();
    tbi.set_acceleration(1000);  // mm/s²
    tbi.output_x.map(&kinematics.input_x);
    tbi.output_y.map(&kinematics.input_y);
    top_up();
  }

  /// The knobs turn and the pen moves as in StepASketchGraph; every 25th frame (each ms) the
  /// loop runs and the queue is topped up (outside the frame); then one frame runs.
  void run_busy_frame(uint32_t frame) {
    if (frame % 25 == 0) {
      engine().run_loop();
      top_up();
    }
    StepASketchGraph::run_busy_frame(frame);
  }

  TimeBasedInterpolator tbi;

 private:
  void top_up() {
    while (!tbi.queue_is_full()) {
      const bool across = (segment_++ % 2) == 0;
      tbi.add_move(INCREMENTAL, 50.0f, across ? 2.0 : 0.0, across ? 0.0 : (up_ ? 2.0 : -2.0), 0, 0, 0, 0);
      if (segment_ % 20 == 0) up_ = !up_;
    }
  }
  uint32_t segment_ = 0;
  bool up_ = true;
};

}  // namespace stepdance::workloads
