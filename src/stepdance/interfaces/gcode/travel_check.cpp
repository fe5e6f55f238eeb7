// Grbl's soft-limit check (limits_soft_check), applied to a whole line before any of it runs.
#include "stepdance/interfaces/gcode/travel_check.hpp"

#include "stepdance/interfaces/gcode/arc_geometry.hpp"

namespace stepdance::gcode {

// A straight move starts where the last one ended, so its end is enough; an arc may bulge past both
// ends, so it is checked by the box it sweeps, worked out in closed form, however many chords it
// makes (docs/gcode.md, row arc-box). E has no travel setting.
bool within_travel(const GrblSettings& settings, const Motion& motion) {
  if (!settings.soft_limits()) return true;
  double low[kAxisCount];
  double high[kAxisCount];
  for (int axis = 0; axis < kAxisCount; ++axis) low[axis] = high[axis] = motion.end_mm[axis];
  if (motion.kind == MotionKind::kArc) arc_bounds_mm(motion, low, high);
  for (int axis = 0; axis < kOffsetAxisCount; ++axis) {
    if (low[axis] < 0.0 || high[axis] > settings.max_travel_mm(axis)) return false;
  }
  return true;
}

}  // namespace stepdance::gcode
