// FiveBarGeometry: circle intersections for the inverse, the original's closed form for forward.
#include "stepdance/motion/five_bar_geometry.hpp"

#include <math.h>

#include "stepdance/motion/sine_cosine.hpp"

namespace stepdance {
namespace {

constexpr double kHalfPi = 1.57079632679489661923;

struct Point {
  double x, y;
};

/// The two intersections of circles (a, ra) and (b, rb); false if they do not meet.
// Standard two-circle intersection: `along` is the distance from a to the chord's midpoint, h half the
// chord. Tangent circles give h = 0 (fmax guards a tiny negative from rounding).
bool intersect(Point a, double ra, Point b, double rb, Point& first, Point& second) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double d = hypot(dx, dy);
  if (d == 0.0 || d > ra + rb || d < fabs(ra - rb)) return false;
  const double along = (ra * ra - rb * rb + d * d) / (2.0 * d);
  const double h = sqrt(fmax(ra * ra - along * along, 0.0));
  const Point mid{a.x + along * dx / d, a.y + along * dy / d};
  first = {mid.x + h * dy / d, mid.y - h * dx / d};
  second = {mid.x - h * dy / d, mid.y + h * dx / d};
  return true;
}

}  // namespace

// The original's closed form (original-library.md §4.10), in double precision, with the acos
// domain checked: base pivots at (±S/2, 0), y is flipped at the end as in the original.
bool FiveBarGeometry::forward(double a1, double a2, double& x, double& y) const {
  // Runs every frame of a pantograph: each angle's sine and cosine share one argument reduction.
  const SineCosine w1 = sine_cosine(a1), w2 = sine_cosine(a2);
  const Point c{s / 2 + l1 * w1.cosine, -l1 * w1.sine};
  const Point d{-s / 2 + l2 * w2.cosine, -l2 * w2.sine};
  const double l6 = d.y - c.y, l7 = c.x - d.x;
  const double a3 = atan2(l6, l7);
  const double l8 = hypot(l6, l7);
  const double cosine = (l8 * l8 + l3 * l3 - l4 * l4) / (2 * l8 * l3);
  if (!(l8 > 0.0) || cosine < -1.0 || cosine > 1.0) return false;  // the links cannot meet
  const double a4 = acos(cosine);
  const SineCosine w5 = sine_cosine(kHalfPi + a3 - a4);  // A5
  const Point e{c.x - l3 * w5.sine, c.y - l3 * w5.cosine};
  const SineCosine w7 = sine_cosine(a6 - a4 + a3);  // A7 = A6 − π/2 + A5
  x = e.x + l5 * w7.cosine;
  y = -(e.y - l5 * w7.sine);
  return true;
}

// No closed form in the original. Up to four candidate poses (2 for C × 2 for D) are solved and each
// is checked by running forward() on it; the one that lands closest to (x, y), within 1e-6 in the
// link lengths' units, wins, so the inverse is consistent with the forward map.
bool FiveBarGeometry::inverse(double x, double y, double& a1, double& a2) const {
  const Point t{x, -y};
  // The rigid link C–E–T: T − C = −L3·w(A5) + L5·w(A5 + A6) with w(φ) = (sin φ, cos φ), so
  // |T − C| is fixed and C lies where that circle round T meets the right arm's circle.
  const double reach = sqrt(fmax(l3 * l3 + l5 * l5 - 2 * l3 * l5 * cos(a6), 0.0));
  Point c_options[2], d_options[2];
  if (!intersect({s / 2, 0}, l1, t, reach, c_options[0], c_options[1])) return false;
  double best_error = INFINITY;
  for (const Point& c : c_options) {
    // A5 from T − C: with w(φ) = i·e^{−iφ} as complex numbers, T − C = i·e^{−iA5}(−L3 + L5·e^{−iA6}).
    const double kx = -l3 + l5 * cos(a6), ky = -l5 * sin(a6);  // −L3 + L5 e^{−iA6}
    const double qx = -ky, qy = kx;                            // i·(that)
    const double vx = t.x - c.x, vy = t.y - c.y;
    // e^{−iA5} = (T − C) / q
    const double norm = qx * qx + qy * qy;
    const double rx = (vx * qx + vy * qy) / norm, ry = (vy * qx - vx * qy) / norm;
    const double a5 = -atan2(ry, rx);
    const Point e{c.x - l3 * sin(a5), c.y - l3 * cos(a5)};
    if (!intersect({-s / 2, 0}, l2, e, l4, d_options[0], d_options[1])) continue;
    for (const Point& d : d_options) {
      const double candidate1 = atan2(-c.y, c.x - s / 2);
      const double candidate2 = atan2(-d.y, d.x + s / 2);
      double fx, fy;
      if (!forward(candidate1, candidate2, fx, fy)) continue;
      const double error = hypot(fx - x, fy - y);
      if (error < best_error) {
        best_error = error;
        a1 = candidate1;
        a2 = candidate2;
      }
    }
  }
  return best_error < 1e-6;
}

}  // namespace stepdance
