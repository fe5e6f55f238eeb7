// Junction deviation: a corner is passed as if on a small circle touching both moves.
#include "stepdance/motion/planner/junction.hpp"

#include <math.h>

namespace stepdance::planner {

double junction_speed(const double (&from)[3], const double (&to)[3], double deviation_mm, double acceleration) {
  const double cos_theta = -(from[0] * to[0] + from[1] * to[1] + from[2] * to[2]);
  if (cos_theta < -0.999999) return INFINITY;  // straight on
  if (cos_theta > 0.999999) return 0.0;        // straight back
  const double sin_half = sqrt(0.5 * (1.0 - cos_theta));
  return sqrt(acceleration * deviation_mm * sin_half / (1.0 - sin_half));
}

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
