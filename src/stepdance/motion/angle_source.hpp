// AngleSource: the advancing angle behind the circle and wave generators (time or an input).
#pragma once

#include <math.h>

#include "stepdance/core/block_port.hpp"
#include "stepdance/core/units.hpp"
#include "stepdance/motion/rate_ramp.hpp"

namespace stepdance {

/// An angle that advances by rate × 40 µs per frame (no input) or by rate × the input's change
/// (rad per input unit), kept in [0, 2π) so it never loses precision however long it runs.
/// Without an input the rate can be ramped (set_angular_acceleration; off by default).
/// Context: frame ISR (owned by one block).
class AngleSource {
 public:
  /// Advances and returns the new angle, radians. `input` has been pulled and updated.
  double advance(double rate, bool use_input, const BlockPort& input) {
    const double step = use_input ? rate * input.read(INCREMENTAL) : ramp_.follow(rate) * frame_period_s();
    theta_ = wrap(theta_ + step);
    return theta_;
  }
  double angle() const { return theta_; }
  void reset() {
    theta_ = 0.0;
    ramp_.reset();
  }
  /// Limits how fast the time-driven rate changes, rad/s²; 0 = no limit. Context: any.
  void set_angular_acceleration(double rad_per_s2) { ramp_.set_limit(rad_per_s2); }

  static constexpr double kTwoPi = 6.283185307179586476925;

  /// x in [0, 2π). A step of less than a turn (every frame but a jump of the input) needs one
  /// subtraction or addition, exact as fmod is (Sterbenz); anything larger goes through fmod.
  static double wrap(double x) {
    if (x >= kTwoPi && x < 2 * kTwoPi) return x - kTwoPi;
    if (x < 0.0 && x >= -kTwoPi) {
      const double up = x + kTwoPi;
      return up < kTwoPi ? up : 0.0;  // a tiny negative x rounds up to 2π itself
    }
    if (x >= 0.0 && x < kTwoPi) return x;
    const double rest = fmod(x, kTwoPi);
    return rest < 0.0 ? (rest + kTwoPi < kTwoPi ? rest + kTwoPi : 0.0) : rest;
  }

 private:
  double theta_ = 0.0;
  RateRamp ramp_;
};

}  // namespace stepdance
