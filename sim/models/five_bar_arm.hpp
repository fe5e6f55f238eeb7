// A five-bar arm (the digital pantograph) whose stylus a hand moves along a path; its two joints
// carry encoders and rest against stops. The model's own geometry turns stylus positions into
// joint angles.
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
  /// Joint angles at power-on (radians).
  double home_right_rad = -1.0471975511965976;  // −60°
  double home_left_rad = 4.1887902047863905;    // 240°
  /// Each joint's stop: the right joint turns only within [right_min_rad, right_min_rad + 2π],
  /// the left only within [left_max_rad − 2π, left_max_rad] (one stop per joint, which it cannot
  /// pass from either side). The original pantograph's arms rest against them at power-on: its
  /// sketches latch the right encoder at −60° (MIN) and the left at 240° (MAX).
  double right_min_rad = -1.0471975511965976;  // −60°
  double left_max_rad = 4.1887902047863905;    // 240°
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
/// mirrored (drawing side positive).
///
/// How the joints follow the hand: up to four poses put the stylus at a point (each arm with its
/// link can bend two ways). The model builds them from the linkage (C where the right arm's
/// circle meets the circle of |T − C| round T, which the rigid C–E–T link fixes; D where the left
/// arm's circle meets (E, L4)), never with the library's inverse, and moves the arm in hops of at
/// most 0.5 mm to the pose that continues its motion: inside the stops, at most 2° from where the
/// joints were, and less than half as far as any other such pose (otherwise the hop is halved,
/// down to 0.5 mm / 2³⁰). At a dead point, where two poses meet (within 0.1° of each other: an
/// arm lies in line with its link), the joints keep turning the way they were turning, as a
/// pushed arm snaps through.
///
/// The joints follow the hand's path itself, through each of its corners.
///
/// Where the hand's path leaves what the arm can reach without passing a stop or a dead point,
/// the stylus stays where the path left it (the joint against its stop, or the links in line)
/// until the hand's straight line from there is reachable again; every moment (each new time an
/// encoder is read) when the stylus is more than 1 µm from the hand counts as unsolved.
///
/// Each joint's counter holds the edges crossed since power-on, counting down as the angle grows:
/// floor(A₀·cpr/2π) − floor(A·cpr/2π). That is how the original's pantograph is built: both of
/// its sketches (`pantograph`, `pantograph_basic_module`) invert both encoders to get the
/// kinematics' angles.
class FiveBarArm {
 public:
  explicit FiveBarArm(const FiveBarArmSettings& settings);

  /// Where the hand holds the stylus at `time` (mm, drawing side positive).
  PenPoint stylus_at(SimTime time) const;
  /// The hand's whole path, from the home position.
  const std::vector<PenPoint>& path() const { return waypoints_; }
  /// Encoder counts of the right (A1) and left (A2) joints at `time`.
  int64_t right_count_at(SimTime time) const;
  int64_t left_count_at(SimTime time) const;
  /// Moments when the stylus could not follow the hand; 0 in a good scenario.
  uint64_t unsolved() const { return unsolved_; }

  /// The forward map (radians → mm, drawing side positive); false when the links cannot meet.
  bool stylus_for(double right_rad, double left_rad, PenPoint& stylus) const;

  /// The linkage's joints (mm, drawing side positive, as the stylus): the pivots, the right and
  /// left arms' ends C and D, the elbow E and the stylus T.
  struct Linkage {
    PenPoint right_pivot, left_pivot, c, d, e, t;
  };
  /// The linkage where the encoders were last read (the arm does not move for the asking);
  /// false when its links cannot meet.
  bool last_linkage(Linkage& linkage) const { return linkage_for(pose_.right, pose_.left, linkage); }
  /// The linkage at joint angles (radians); false when the links cannot meet.
  bool linkage_for(double right_rad, double left_rad, Linkage& linkage) const;

 private:
  struct Angles {
    double right = 0;
    double left = 0;
  };
  struct Poses {
    Angles pose[4];
    int count = 0;
  };
  double since_start_s(SimTime time) const;
  Angles angles_at(SimTime time) const;
  void walk_to(const PenPoint& target) const;
  bool advance(const PenPoint& to, int depth) const;
  int choose(const Poses& poses, bool shortest_hop) const;
  Poses poses_for(const PenPoint& target, const Angles& near) const;
  bool inside_stops(Angles& angles) const;
  int64_t edges(double angle_rad) const;

  FiveBarArmSettings settings_;
  std::vector<PenPoint> waypoints_;  ///< home stylus position, then the path
  std::vector<double> arrival_s_;    ///< seconds after start each waypoint is reached
  std::vector<double> leave_s_;      ///< ... and left (after its dwell)
  // Where the arm is: its joints, its stylus, its last turn and whether it is at a dead point.
  mutable SimTime solved_time_ = -1;
  mutable Angles pose_;
  mutable PenPoint stylus_;
  mutable Angles last_turn_;
  mutable bool at_dead_point_ = false;
  mutable uint64_t unsolved_ = 0;
};

}  // namespace stepdance::sim
