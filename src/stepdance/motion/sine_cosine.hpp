// SineCosine: sin and cos of one angle with one argument reduction.
#pragma once

#include <math.h>

namespace stepdance {

/// sin θ and cos θ of an angle in radians.
struct SineCosine {
  double sine = 0;
  double cosine = 0;
};

/// sin θ and cos θ together. The angle is reduced once to r in [−π/4, π/4] plus a whole number
/// k of quarter turns (π/2 split in two parts, so k·π/2 is subtracted exactly for |k| < 2²⁰,
/// i.e. |θ| below about 1.6 million rad), then sin r and cos r are rotated by k quarter turns.
/// Both library calls then take their short path (no argument reduction of their own), which
/// is what the frame pays for a polar machine. Results match sin(θ) and cos(θ) to within a few
/// units in the last place; larger angles fall back to the library's own reduction.
/// Context: any.
inline SineCosine sine_cosine(double theta) {
  constexpr double kTwoOverPi = 6.36619772367581382433e-01;
  constexpr double kHalfPiHigh = 1.57079632673412561417e+00;  // π/2's leading 33 bits
  constexpr double kHalfPiLow = 6.07710050650619224932e-11;   // π/2 − kHalfPiHigh
  constexpr double kLargest = 1.6e6;
  if (!(fabs(theta) < kLargest)) return SineCosine{sin(theta), cos(theta)};
  const double k = nearbyint(theta * kTwoOverPi);
  const double r = (theta - k * kHalfPiHigh) - k * kHalfPiLow;
  const double s = sin(r);
  const double c = cos(r);
  switch (static_cast<long>(k) & 3) {
    case 0: return SineCosine{s, c};
    case 1: return SineCosine{c, -s};
    case 2: return SineCosine{-s, -c};
    default: return SineCosine{-c, s};
  }
}

}  // namespace stepdance
