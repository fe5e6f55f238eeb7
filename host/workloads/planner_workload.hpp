// The look-ahead planner in steady state, shared by the host benchmark and the M7 image.
#pragma once

#include <math.h>
#include <stdint.h>

#include "stepdance/motion/planner/lookahead_planner.hpp"
#include "stepdance/motion/planner/motion_limits.hpp"

namespace stepdance::workloads {

/// A full 128-block look-ahead queue fed with short segments of a gently turning polyline
/// (0.2 mm long, turning 2° each, CoreXY joint limits): every step() hands the oldest block out
/// (as the frame would take it) and plans one new segment, re-running both passes over the queue.
/// One step() is one planned segment.
class PlannerWorkload {
 public:
  PlannerWorkload() {
    limits_.use_core_xy(150.0, 2000.0);
    limits_.set_default_acceleration(1500.0);
    while (!planner_.full()) add_next();
  }

  void step() {
    planner::PlannedBlock out;
    planner_.take_final(out, true);
    checksum_ += out.exit_speed;
    add_next();
  }

  /// Sum of exit speeds handed out (keeps the work observable).
  double checksum() const { return checksum_; }

 private:
  void add_next() {
    planner::PlannedBlock block;
    heading_rad_ += 2.0 * 3.14159265358979 / 180.0;
    block.delta[0] = 0.2 * cos(heading_rad_);
    block.delta[1] = 0.2 * sin(heading_rad_);
    block.length = 0.2;
    block.cruise_speed = limits_.max_speed(block.delta, block.length);
    if (block.cruise_speed > 60.0) block.cruise_speed = 60.0;
    block.acceleration = limits_.max_acceleration(block.delta, block.length);
    planner_.add(block);
  }

  planner::MotionLimits limits_;
  planner::LookaheadPlanner planner_;
  double heading_rad_ = 0.0;
  double checksum_ = 0.0;
};

}  // namespace stepdance::workloads
