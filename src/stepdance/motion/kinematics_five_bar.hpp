// KinematicsFiveBarForward / Inverse: the digital pantograph's arm angles and its tool position.
#pragma once

#include <stdint.h>

#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/core/units.hpp"
#include "stepdance/motion/five_bar_geometry.hpp"

namespace stepdance {

/// Arm angles (input_r = A1 of the right arm, input_l = A2 of the left, radians) to the tool
/// position (output_x, output_y, mm), set absolutely each frame (see FiveBarGeometry). A pose the
/// links cannot reach holds the last reachable output, is counted and reported as a warning
/// (FaultReason::kUnreachable) — never a NaN. Context: run() in the frame; begin in the loop.
class KinematicsFiveBarForward : public Block {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "KinematicsFiveBarForward"; }
  /// Pivot spacing S, arms L1 (right) and L2 (left), links L3 and L4, tool extension L5 (mm),
  /// tool angle A6 (rad). Context: loop.
  Status begin(float s, float l1, float l2, float l3, float l4, float l5, float a6);
  void run() override;
  /// Frames whose pose was out of reach. Context: any.
  uint32_t unreachable_count() const { return unreachable_; }
  /// unreachable. Context: loop.
  void report_counters(CounterSink& sink) const override { sink.counter("unreachable", unreachable_); }

  BlockPort input_r;
  BlockPort input_l;
  BlockPort output_x;
  BlockPort output_y;

 private:
  FiveBarGeometry geometry_;
  volatile uint32_t unreachable_ = 0;
  DecimalPosition r_ = 0, l_ = 0, x_ = 0, y_ = 0;
};

/// The other way: a tool position (input_x, input_y) to the arm angles (output_r, output_l)
/// that reach it, for driving a five-bar arm from XY motion. Unreachable points hold the last
/// angles, are counted and reported, as above.
class KinematicsFiveBarInverse : public Block {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "KinematicsFiveBarInverse"; }
  Status begin(float s, float l1, float l2, float l3, float l4, float l5, float a6);
  void run() override;
  uint32_t unreachable_count() const { return unreachable_; }
  /// unreachable. Context: loop.
  void report_counters(CounterSink& sink) const override { sink.counter("unreachable", unreachable_); }

  BlockPort input_x;
  BlockPort input_y;
  BlockPort output_r;
  BlockPort output_l;

 private:
  FiveBarGeometry geometry_;
  volatile uint32_t unreachable_ = 0;
  DecimalPosition x_ = 0, y_ = 0, r_ = 0, l_ = 0;
};

}  // namespace stepdance
