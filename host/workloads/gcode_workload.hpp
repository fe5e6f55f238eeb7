// G-code lines parsed, executed and planned in steady state, shared by the host benchmark and the
// M7 image: the Grbl link's whole per-line path (receive buffer, parser, interpreter, `ok`) with
// a full 128-block look-ahead queue behind it.
#pragma once

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "stepdance/core/byte_stream.hpp"
#include "stepdance/core/text_writer.hpp"
#include "stepdance/interfaces/gcode/grbl_protocol.hpp"
#include "stepdance/motion/planner/lookahead_planner.hpp"
#include "stepdance/motion/planner/motion_limits.hpp"

namespace stepdance::workloads {

/// Hands the link one line of a fixed program per next_line(): first "G21 G90 G1 F3000", then
/// the polygon round and round. Replies vanish.
class LoopingProgram final : public ByteStream {
 public:
  /// A 180-gon with 0.2 mm sides (2° turn per line), absolute coordinates to the micrometre:
  /// lines like "G1 X5.729 Y0.100", the short segments of a sliced or converted drawing.
  LoopingProgram() {
    const double radius_mm = 0.1 / sin(3.14159265358979 / 180.0);
    for (int k = 0; k < kLines; ++k) {
      const double angle = 2.0 * 3.14159265358979 * k / kLines;
      TextWriter line(text_[k], sizeof(text_[k]));
      line.text("G1 X").fixed(radius_mm * cos(angle), 3).text(" Y").fixed(radius_mm * sin(angle), 3).character('\n');
      length_[k] = line.size();
    }
    TextWriter setup(text_[kLines], sizeof(text_[kLines]));
    setup.text("G21 G90 G1 F3000\n");
    length_[kLines] = setup.size();
  }
  /// Makes the next line of the program readable.
  void next_line() {
    line_ = line_ >= kLines - 1 ? 0 : line_ + 1;
    read_ = 0;
  }
  size_t bytes_available() override { return length_[line_] - read_; }
  int read_byte() override { return read_ < length_[line_] ? static_cast<uint8_t>(text_[line_][read_++]) : -1; }
  size_t write_bytes(const uint8_t*, size_t length) override { return length; }
  size_t write_space() override { return 4096; }

 private:
  static constexpr int kLines = 180;
  char text_[kLines + 1][32] = {};
  size_t length_[kLines + 1] = {};
  int line_ = kLines;  // the setup line
  size_t read_ = 0;
};

/// A machine that plans every motion into a full look-ahead queue (handing the oldest block out
/// when it needs room, as the frame would) the way the interpolator does: straight-line length,
/// the feed capped by the axis limits, the acceleration along the path.
class PlanningMachine final : public gcode::GrblMachine {
 public:
  PlanningMachine() {
    for (int axis = 0; axis < 3; ++axis) limits_.set_axis_limit(axis, 100.0, 1000.0);
  }
  void on_motion(const gcode::Motion& motion) override {
    planner::PlannedBlock block;
    double length_sq = 0.0;
    for (int axis = 0; axis < 3; ++axis) {
      block.end[axis] = motion.end_mm[axis];
      block.delta[axis] = block.end[axis] - planned_end_[axis];
      length_sq += block.delta[axis] * block.delta[axis];
    }
    block.length = sqrt(length_sq);
    if (block.length <= 0.0) return;
    const double limit = limits_.max_speed(block.delta, block.length);
    const double requested = motion.feed_mm_per_min / 60.0;
    block.cruise_speed = requested > 0.0 && requested < limit ? requested : limit;
    block.acceleration = limits_.max_acceleration(block.delta, block.length);
    if (planner_.full()) {
      planner::PlannedBlock out;
      planner_.take_final(out, true);
      checksum_ += out.exit_speed;
    }
    planner_.add(block);
    for (int axis = 0; axis < 3; ++axis) planned_end_[axis] = block.end[axis];
  }
  void on_dwell(double) override {}
  gcode::MotionState motion_state() override { return gcode::MotionState::kRun; }
  bool hold_complete() override { return false; }
  void position_mm(double (&out)[gcode::kAxisCount]) override {
    for (double& value : out) value = 0.0;
  }
  double feed_now_mm_per_min() override { return 0.0; }
  uint16_t queue_slots_free() override { return static_cast<uint16_t>(planner_.free_slots()); }
  uint16_t queue_slots_total() override { return static_cast<uint16_t>(planner::LookaheadPlanner::kCapacity); }
  bool ready_for_line() override { return true; }
  void feed_hold() override {}
  void cycle_start() override {}
  bool soft_reset() override { return false; }
  void jog(const gcode::Motion&) override {}
  void jog_cancel() override {}
  void set_overrides(uint8_t, uint8_t) override {}
  double steps_per_mm(int) override { return 80.0; }

  /// Sum of exit speeds handed out (keeps the work observable).
  double checksum() const { return checksum_; }

 private:
  planner::MotionLimits limits_;
  planner::LookaheadPlanner planner_;
  double planned_end_[3] = {};
  double checksum_ = 0.0;
};

/// One step() = one G-code line received, parsed, validated, executed, acknowledged and planned.
class GcodeLineWorkload {
 public:
  GcodeLineWorkload() {
    protocol_.begin(program_, machine_);
    protocol_.poll();  // the setup line
    while (machine_.queue_slots_free() > 0) step();
  }
  void step() {
    program_.next_line();
    protocol_.poll();
  }
  double checksum() const { return machine_.checksum(); }

 private:
  LoopingProgram program_;
  PlanningMachine machine_;
  gcode::GrblProtocol protocol_;
};

}  // namespace stepdance::workloads
