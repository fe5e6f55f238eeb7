// A five-bar arm (the digital pantograph) whose stylus a hand moves along a path; its two joints
// carry encoders. The model's own geometry turns stylus positions into joint angles.
#pragma once

#include <cstdint>
#include <vector>

#include "common/sim_time.hpp"
#include "models/pen_trace.hpp"

namespace stepdance::sim {

/// The arm's build (the original library's pantograph parameters) and the hand's path.
struct FiveBarArmSettings {
  /// Pivot spacing S; right arm L1, left arm L2; links L3 (from the right arm) and L4 (from the
  /// left) meeting at the elbow; the stylus on an extension L5 of the L3 link at angle A6.
  double s_mm = 60, l1_mm = 145.75, l2_mm = 134, l3_mm = 169, l4_mm = 178.3, l5_mm = 28.82;
  double a6_rad = 2.9019;
  /// Joint angles at power-on, where the arms rest against their stops (radians).
  double home_right_rad = -1.0471975511965976;  // −60°
  double home_left_rad = 4.1887902047863905;    // 240°
  /// Encoder pulses per revolution per channel (×4 = counts per revolution).
  int32_t pulses_per_revolution = 10000;
  /// The stylus leaves its home position at `start` and visits these points in order, in
  /// straight lines at `speed_mm_per_s` (drawing-side coordinates, as the library reports them),
  /// resting dwell_s[i] seconds at point i (missing entries: no rest).
  std::vector<PenPoint> path_mm;
  std::vector<double> dwell_s;
  double speed_mm_per_s = 20;
  SimTime start = 0;
};

/// Geometry (pivots at (±S/2, 0) in the arm's own frame, the drawing side at negative y): the
/// right arm's end C = (S/2 + L1·cos A1, −L1·sin A1), the left's D = (−S/2 + L2·cos A2,
/// −L2·sin A2); the elbow E is where circles (C, L3) and (D, L4) meet on the drawing side; the
/// stylus T = E + L5 · (C − E)/L3 turned clockwise by A6. Positions are reported with y
/// mirrored (drawing side positive). Joint angles for a stylus position are found by Newton's
/// method on that forward map, starting from the previous answer (the hand moves smoothly), so
/// nothing here comes from the library's inverse kinematics.
///
/// Each joint's counter holds the edges crossed since power-on, counting down as the angle grows:
/// floor(A₀·cpr/2π) − floor(A·cpr/2π). That is how the original's pantograph is built: both of
/// its sketches (`pantograph`, `pantograph_basic_module`) invert both encoders to get the
/// kinematics' angles.
class FiveBarArm {
 public:
  explicit FiveBarArm(const FiveBarArmSettings& settings);

  /// Stylus position at `time` (mm, drawing side positive).
  PenPoint stylus_at(SimTime time) const;
  /// The hand's whole path, from the home position.
  const std::vector<PenPoint>& path() const { return waypoints_; }
  /// Encoder counts of the right (A1) and left (A2) joints at `time`.
  int64_t right_count_at(SimTime time) const;
  int64_t left_count_at(SimTime time) const;
  /// Stylus positions whose angles could not be solved (out of reach); 0 in a good scenario.
  uint64_t unsolved() const { return unsolved_; }

  /// The forward map (radians → mm, drawing side positive); false when the links cannot meet.
  bool stylus_for(double right_rad, double left_rad, PenPoint& stylus) const;

 private:
  struct Angles {
    double right = 0;
    double left = 0;
  };
  Angles angles_at(SimTime time) const;
  bool solve(const PenPoint& target, Angles& angles) const;
  int64_t edges(double angle_rad) const;

  FiveBarArmSettings settings_;
  std::vector<PenPoint> waypoints_;       ///< home stylus position, then the path
  std::vector<double> arrival_s_;         ///< seconds after start each waypoint is reached
  std::vector<double> leave_s_;           ///< ... and left (after its dwell)
  mutable SimTime solved_time_ = -1;
  mutable Angles solved_;
  mutable PenPoint solved_point_;
  mutable uint64_t unsolved_ = 0;
};

}  // namespace stepdance::sim
