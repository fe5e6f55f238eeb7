// The unit of planned motion: a straight move with its speed profile limits.
#pragma once

#include <stdint.h>

namespace stepdance::planner {

/// Axes of planned motion, in the TimeBasedInterpolator's output order.
enum PlannerAxis : uint8_t { kX = 0, kY, kZ, kE, kR, kT };
constexpr int kPlannerAxes = 6;

/// A straight move in world units (mm for X/Y/Z/E, radians or the sketch's units for R/T).
/// The planner fills the speeds; once committed to the frame a block never changes.
struct PlannedBlock {
  double delta[kPlannerAxes] = {};    ///< displacement of each axis
  double end[kPlannerAxes] = {};      ///< where each axis ends (world units), written exactly at the end
  double length = 0.0;                ///< path length the speeds refer to (XYZ, else E, else R/T)
  double cruise_speed = 0.0;          ///< highest speed along the path, units/s
  double entry_speed = 0.0;           ///< speed at the start, units/s (planner's result)
  double exit_speed = 0.0;            ///< speed at the end, units/s (planner's result)
  double max_entry_speed = 0.0;       ///< junction limit with the previous block, units/s
  double acceleration = 0.0;          ///< along the path, units/s²
  double dwell_s = 0.0;               ///< zero-length timed block: wait this long
  double requested_duration_s = 0.0;  ///< timed moves: the duration asked for (else 0)
  uint32_t id = 0;                    ///< sequence number, for reports
};

}  // namespace stepdance::planner
