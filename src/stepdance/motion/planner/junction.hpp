// Corner speed between two straight moves by the junction-deviation model.
#pragma once

namespace stepdance::planner {

/// Highest speed at which a path may turn from direction `from` into direction `to` (unit vectors
/// in XYZ) so that a circle of deviation `deviation_mm` from the corner, tangent to both moves,
/// is followed with centripetal acceleration `acceleration` (units/s²):
///   v² = a·δ·s / (1 − s), s = sin(θ/2), θ = angle between −from and to.
/// Straight on gives +infinity (no corner), a full reversal 0. Context: any (pure).
double junction_speed(const double (&from)[3], const double (&to)[3], double deviation_mm, double acceleration);

/// Highest corner speed for chains of short moves approximating a curve: the arc tangent to both
/// moves at the middle of the shorter one has radius ρ = (L/2)·tan(θ/2), and v² = a·ρ. On a circle
/// cut into N chords this is the circle's own centripetal limit, v² ≈ a·R. Context: any (pure).
double centripetal_junction_speed(const double (&from)[3], const double (&to)[3], double shorter_length,
                                  double acceleration);

}  // namespace stepdance::planner
