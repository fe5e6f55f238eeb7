// Speed and acceleration limits of a machine, per axis and per joint, and what they allow along a direction.
#pragma once

#include <stdint.h>

#include "stepdance/motion/planner/planned_block.hpp"

namespace stepdance::planner {

/// Limits that hold at the motors. Each joint's velocity is a linear combination of the planner
/// axes (a row), so CoreXY (a = x + y, b = x − y) and plain cartesian axes (a row with a single
/// 1) are described alike. Values of 0 mean "unlimited". Context: loop only.
class MotionLimits {
 public:
  static constexpr int kMaxJoints = 8;

  /// Limits every planner axis on its own (speed in units/s, acceleration in units/s²).
  void set_axis_limit(int axis, double max_speed, double max_acceleration);
  /// Adds a joint whose speed is Σ row[i]·v_i. Returns false when kMaxJoints are in use.
  bool add_joint(const double (&row)[kPlannerAxes], double max_speed, double max_acceleration);
  /// CoreXY on X/Y: joints a = x + y and b = x − y, each limited as given.
  void use_core_xy(double motor_max_speed, double motor_max_acceleration);
  /// Removes every joint (axis limits stay).
  void clear_joints() { joint_count_ = 0; }
  /// Path acceleration used when no limit applies (units/s²); 0 = unlimited.
  void set_default_acceleration(double acceleration) { default_acceleration_ = acceleration; }
  double default_acceleration() const { return default_acceleration_; }

  /// Highest path speed and acceleration that keep every axis and joint within its limits while
  /// moving along `delta` (any length; only its direction matters, length > 0).
  double max_speed(const double (&delta)[kPlannerAxes], double length) const;
  double max_acceleration(const double (&delta)[kPlannerAxes], double length) const;

 private:
  double limit_along(const double (&delta)[kPlannerAxes], double length, bool speed) const;

  double axis_speed_[kPlannerAxes] = {};
  double axis_acceleration_[kPlannerAxes] = {};
  double joint_row_[kMaxJoints][kPlannerAxes] = {};
  double joint_speed_[kMaxJoints] = {};
  double joint_acceleration_[kMaxJoints] = {};
  int joint_count_ = 0;
  double default_acceleration_ = 0.0;
};

}  // namespace stepdance::planner
