// Arc geometry for G2/G3: centre from either form, sweep direction, chord splitting.
#include "stepdance/interfaces/gcode/arc_geometry.hpp"

#include <math.h>

namespace stepdance::gcode {
namespace {

constexpr double kPi = 3.14159265358979323846;
/// Sweeps closer to zero than this count as a full turn (start and end coincide).
constexpr double kFullTurnEpsilonRad = 1e-7;

/// Sets the signed sweep from start to end around the centre already stored in arc.
// The signed angle from start to end around the centre (atan2 of cross and dot products), then
// forced to the commanded direction: G2 negative, G3 positive. Start = end makes a full circle.
void set_sweep(Motion& arc, bool clockwise) {
  const double v0_0 = arc.start_mm[arc.plane_axis_0] - arc.center_0_mm;
  const double v0_1 = arc.start_mm[arc.plane_axis_1] - arc.center_1_mm;
  const double v1_0 = arc.end_mm[arc.plane_axis_0] - arc.center_0_mm;
  const double v1_1 = arc.end_mm[arc.plane_axis_1] - arc.center_1_mm;
  double sweep = atan2(v0_0 * v1_1 - v0_1 * v1_0, v0_0 * v1_0 + v0_1 * v1_1);
  if (clockwise && sweep >= -kFullTurnEpsilonRad) sweep -= 2.0 * kPi;
  if (!clockwise && sweep <= kFullTurnEpsilonRad) sweep += 2.0 * kPi;
  arc.sweep_rad = sweep;
  arc.kind = MotionKind::kArc;
}

}  // namespace

// Grbl's radius check for the offset form: start and end radius may differ by 0.005 mm, or by up to
// 0.5 mm if that is within 0.1 % of the radius; beyond, error:33.
GrblError complete_arc_ijk(Motion& arc, bool clockwise, double offset_0_mm, double offset_1_mm) {
  arc.center_0_mm = arc.start_mm[arc.plane_axis_0] + offset_0_mm;
  arc.center_1_mm = arc.start_mm[arc.plane_axis_1] + offset_1_mm;
  const double start_radius = hypot(offset_0_mm, offset_1_mm);
  const double end_radius =
      hypot(arc.end_mm[arc.plane_axis_0] - arc.center_0_mm, arc.end_mm[arc.plane_axis_1] - arc.center_1_mm);
  const double difference = fabs(end_radius - start_radius);
  if (difference > 0.005 && (difference > 0.5 || difference > 0.001 * start_radius)) {
    return GrblError::kInvalidTarget;
  }
  if (start_radius <= 0.0) return GrblError::kInvalidTarget;
  arc.radius_mm = start_radius;
  set_sweep(arc, clockwise);
  return GrblError::kOk;
}

// Radius form (Grbl's gc_execute_line): the centre lies on the chord's perpendicular bisector at
// height √(r² − (c/2)²); a negative R asks for the arc longer than half a circle. Start = end has
// no defined centre (error:33); a radius too short for the chord is error:34.
GrblError complete_arc_radius(Motion& arc, bool clockwise, double radius_mm) {
  const double chord_0 = arc.end_mm[arc.plane_axis_0] - arc.start_mm[arc.plane_axis_0];
  const double chord_1 = arc.end_mm[arc.plane_axis_1] - arc.start_mm[arc.plane_axis_1];
  const double chord = hypot(chord_0, chord_1);
  if (chord == 0.0) return GrblError::kInvalidTarget;
  const double radius = fabs(radius_mm);
  double height_squared = radius * radius - chord * chord / 4.0;
  if (height_squared < 0.0) {
    // A radius equal to half the chord, written with rounded decimals, may fall short by a hair.
    if (height_squared < -1e-9 * radius * radius) return GrblError::kArcRadiusError;
    height_squared = 0.0;
  }
  // Counter-clockwise short arcs have their centre left of the chord; each flip moves it across.
  double side = clockwise ? -1.0 : 1.0;
  if (radius_mm < 0.0) side = -side;
  const double height = side * sqrt(height_squared);
  arc.center_0_mm = arc.start_mm[arc.plane_axis_0] + chord_0 / 2.0 - height * chord_1 / chord;
  arc.center_1_mm = arc.start_mm[arc.plane_axis_1] + chord_1 / 2.0 + height * chord_0 / chord;
  arc.radius_mm = radius;
  set_sweep(arc, clockwise);
  return GrblError::kOk;
}

// The box an arc sweeps, for the soft-limit check before the arc runs: the end points, widened by each
// axis extreme (0°, 90°, 180°, 270°) that the sweep passes.
void arc_bounds_mm(const Motion& arc, double (&low_mm)[kAxisCount], double (&high_mm)[kAxisCount]) {
  for (int axis = 0; axis < kAxisCount; ++axis) {
    low_mm[axis] = fmin(arc.start_mm[axis], arc.end_mm[axis]);
    high_mm[axis] = fmax(arc.start_mm[axis], arc.end_mm[axis]);
  }
  const double start_rad =
      atan2(arc.start_mm[arc.plane_axis_1] - arc.center_1_mm, arc.start_mm[arc.plane_axis_0] - arc.center_0_mm);
  const double sweep = fabs(arc.sweep_rad);
  const double direction = arc.sweep_rad < 0.0 ? -1.0 : 1.0;
  // The extreme points in turn: +axis 0, +axis 1, -axis 0, -axis 1 (0°, 90°, 180°, 270°).
  for (int quadrant = 0; quadrant < 4; ++quadrant) {
    // How far the sweep must go from the start to reach this extreme, in [0, 2π).
    double to_extreme = fmod(direction * (quadrant * kPi / 2.0 - start_rad), 2.0 * kPi);
    if (to_extreme < 0.0) to_extreme += 2.0 * kPi;
    if (to_extreme > sweep) continue;
    const int axis = quadrant % 2 == 0 ? arc.plane_axis_0 : arc.plane_axis_1;
    const double center = quadrant % 2 == 0 ? arc.center_0_mm : arc.center_1_mm;
    if (quadrant < 2) high_mm[axis] = fmax(high_mm[axis], center + arc.radius_mm);
    if (quadrant >= 2) low_mm[axis] = fmin(low_mm[axis], center - arc.radius_mm);
  }
}

// Chords short enough that none strays more than the tolerance ($12) from the true arc, at most a
// quarter turn each; the tolerance is floored at 1 µm so a tiny setting cannot ask for millions of
// chords. Grbl splits by the same criterion (mc_arc).
ArcSegmenter::ArcSegmenter(const Motion& arc, double tolerance_mm) : arc_(arc) {
  const double tolerance = tolerance_mm < 1e-3 ? 1e-3 : tolerance_mm;
  // A chord spanning angle a deviates r(1 - cos(a/2)) from the arc.
  double max_angle = kPi / 2.0;
  if (tolerance < arc.radius_mm) {
    const double exact = 2.0 * acos(1.0 - tolerance / arc.radius_mm);
    if (exact < max_angle) max_angle = exact;
  }
  const double needed = ceil(fabs(arc.sweep_rad) / max_angle);
  if (needed > kMaxSegments) {
    count_ = kMaxSegments;
  } else if (needed > 1.0) {
    count_ = static_cast<uint32_t>(needed);
  }
}

// Chord end k: in-plane on the circle, the helix axis and E linear in the fraction. The last point
// is the arc's exact end, so rounding never leaves the arc short.
void ArcSegmenter::point_mm(uint32_t k, double (&out)[kAxisCount]) const {
  if (k >= count_) {
    for (int axis = 0; axis < kAxisCount; ++axis) out[axis] = arc_.end_mm[axis];
    return;
  }
  const double fraction = static_cast<double>(k) / count_;
  for (int axis = 0; axis < kAxisCount; ++axis) {
    out[axis] = arc_.start_mm[axis] + fraction * (arc_.end_mm[axis] - arc_.start_mm[axis]);
  }
  const double start_angle =
      atan2(arc_.start_mm[arc_.plane_axis_1] - arc_.center_1_mm, arc_.start_mm[arc_.plane_axis_0] - arc_.center_0_mm);
  const double angle = start_angle + fraction * arc_.sweep_rad;
  out[arc_.plane_axis_0] = arc_.center_0_mm + arc_.radius_mm * cos(angle);
  out[arc_.plane_axis_1] = arc_.center_1_mm + arc_.radius_mm * sin(angle);
}

}  // namespace stepdance::gcode
