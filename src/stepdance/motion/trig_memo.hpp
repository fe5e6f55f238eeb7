// TrigMemo: sine and cosine that remember their last argument.
#pragma once

#include <math.h>

namespace stepdance {

/// A generator that moves by f(θ₁) − f(θ₀) each frame asks for f at the angle where the last
/// frame ended; remembering the last argument saves recomputing it (about half the trigonometry
/// of the circle and wave generators). Exact: a hit returns the value computed for the very same
/// argument. Context: the owning block's frame.
class TrigMemo {
 public:
  /// sin(x).
  double sine(double x) {
    if (!(has_sine_ && x == sine_x_)) {
      sine_x_ = x;
      sine_ = sin(x);
      has_sine_ = true;
    }
    return sine_;
  }
  /// cos(x).
  double cosine(double x) {
    if (!(has_cosine_ && x == cosine_x_)) {
      cosine_x_ = x;
      cosine_ = cos(x);
      has_cosine_ = true;
    }
    return cosine_;
  }

 private:
  double sine_x_ = 0, sine_ = 0, cosine_x_ = 0, cosine_ = 0;
  bool has_sine_ = false, has_cosine_ = false;
};

}  // namespace stepdance
