// Junction deviation: a corner is passed as if on a small circle touching both moves.
#include "stepdance/motion/planner/junction.hpp"

#include <math.h>

namespace stepdance::planner {

// Grbl's junction deviation: the corner is taken as a circular arc whose closest point stays
// deviation_mm from the vertex, at centripetal acceleration a: v² = a·δ·sin(θ/2)/(1 − sin(θ/2)), with
// θ the angle between the reversed incoming and the outgoing unit directions (docs/planner.md
// "Corners"). Nearly straight: no limit; a full reversal: stop.
double junction_speed(const double (&from)[3], const double (&to)[3], double deviation_mm, double acceleration) {
  const double cos_theta = -(from[0] * to[0] + from[1] * to[1] + from[2] * to[2]);
  if (cos_theta < -0.999999) return INFINITY;  // straight on
  if (cos_theta > 0.999999) return 0.0;        // straight back
  const double sin_half = sqrt(0.5 * (1.0 - cos_theta));
  return sqrt(acceleration * deviation_mm * sin_half / (1.0 - sin_half));
}

// A second bound so a polyline approximating a curve runs at the curve's own speed: the arc that
// touches both segments at half the shorter one's length has radius (L/2)·tan(θ/2), and v² = a·r.
double centripetal_junction_speed(const double (&from)[3], const double (&to)[3], double shorter_length,
                                  double acceleration) {
  const double cos_theta = -(from[0] * to[0] + from[1] * to[1] + from[2] * to[2]);
  if (cos_theta < -0.999999) return INFINITY;
  if (cos_theta > 0.999999) return 0.0;
  // tan(θ/2) = sin θ / (1 + cos θ)
  const double tan_half = sqrt(1.0 - cos_theta * cos_theta) / (1.0 + cos_theta);
  return sqrt(acceleration * 0.5 * shorter_length * tan_half);
}

}  // namespace stepdance::planner
