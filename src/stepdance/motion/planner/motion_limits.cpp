// Direction-dependent limits: the tightest of every axis and joint.
#include "stepdance/motion/planner/motion_limits.hpp"

#include <math.h>

namespace stepdance::planner {

void MotionLimits::set_axis_limit(int axis, double max_speed, double max_acceleration) {
  if (axis < 0 || axis >= kPlannerAxes) return;
  axis_speed_[axis] = fabs(max_speed);
  axis_acceleration_[axis] = fabs(max_acceleration);
}

// A joint is a motor whose motion is a linear combination of the axes (row · delta), e.g. CoreXY's
// a = x + y; limiting it keeps every motor within its rating whatever the path direction.
bool MotionLimits::add_joint(const double (&row)[kPlannerAxes], double max_speed, double max_acceleration) {
  if (joint_count_ == kMaxJoints) return false;
  for (int i = 0; i < kPlannerAxes; ++i) joint_row_[joint_count_][i] = row[i];
  joint_speed_[joint_count_] = fabs(max_speed);
  joint_acceleration_[joint_count_] = fabs(max_acceleration);
  ++joint_count_;
  return true;
}

// CoreXY motors a = x + y, b = x − y (original-library.md §4.10): a diagonal move drives one motor at
// twice the axis share, so it is limited by that motor, not by the axis limits.
void MotionLimits::use_core_xy(double motor_max_speed, double motor_max_acceleration) {
  const double a[kPlannerAxes] = {1.0, 1.0, 0.0, 0.0, 0.0, 0.0};
  const double b[kPlannerAxes] = {1.0, -1.0, 0.0, 0.0, 0.0, 0.0};
  add_joint(a, motor_max_speed, motor_max_acceleration);
  add_joint(b, motor_max_speed, motor_max_acceleration);
}

double MotionLimits::limit_along(const double (&delta)[kPlannerAxes], double length, bool speed) const {
  double limit = INFINITY;
  // A quantity moving `share` units per path unit reaches its own limit L at path rate L / share.
  auto tighten = [&limit](double own_limit, double share) {
    share = fabs(share);
    if (own_limit > 0.0 && share > 1e-12 && own_limit / share < limit) limit = own_limit / share;
  };
  for (int axis = 0; axis < kPlannerAxes; ++axis) {
    tighten(speed ? axis_speed_[axis] : axis_acceleration_[axis], delta[axis] / length);
  }
  for (int joint = 0; joint < joint_count_; ++joint) {
    double share = 0.0;
    for (int axis = 0; axis < kPlannerAxes; ++axis) share += joint_row_[joint][axis] * delta[axis] / length;
    tighten(speed ? joint_speed_[joint] : joint_acceleration_[joint], share);
  }
  return limit;
}

double MotionLimits::max_speed(const double (&delta)[kPlannerAxes], double length) const {
  return limit_along(delta, length, true);
}

// The default acceleration applies when it is tighter than every axis and joint limit (or none is
// set), so a sketch without limits still gets a finite, trapezoidal profile.
double MotionLimits::max_acceleration(const double (&delta)[kPlannerAxes], double length) const {
  const double limit = limit_along(delta, length, false);
  if (default_acceleration_ > 0.0 && default_acceleration_ < limit) return default_acceleration_;
  return limit;
}

}  // namespace stepdance::planner
