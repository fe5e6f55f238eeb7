// RateRamp: an optional acceleration limit for the velocity-like generators.
#pragma once

#include <math.h>

#include "stepdance/core/units.hpp"

namespace stepdance {

/// Follows a target rate (a speed, an angular rate) frame by frame, changing it by at most
/// limit × 40 µs per frame, so a knob or pedal that jumps makes the motion ramp instead of step.
/// A limit of 0 (the default) follows the target at once. Units: the rate's per second.
/// Context: follow() in the frame ISR of the owning block; set_limit() any.
class RateRamp {
 public:
  /// Largest change of the rate per second (its magnitude is used); 0 turns the limit off.
  void set_limit(double rate_change_per_s) { limit_per_s_ = fabs(rate_change_per_s); }
  double limit() const { return limit_per_s_; }

  /// The rate to use this frame: the target, or as close to it as the limit allows.
  double follow(double target) {
    if (limit_per_s_ == 0.0) {
      current_ = target;
      return current_;
    }
    const double most = limit_per_s_ * frame_period_s();
    const double change = target - current_;
    current_ = fabs(change) <= most ? target : current_ + copysign(most, change);
    return current_;
  }
  /// The rate last used. Context: any.
  double current() const { return current_; }
  /// Starts from rest. Context: loop.
  void reset() { current_ = 0.0; }

 private:
  double limit_per_s_ = 0.0;
  double current_ = 0.0;
};

}  // namespace stepdance
