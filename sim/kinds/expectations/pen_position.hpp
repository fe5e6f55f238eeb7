// Expectation kind "pen_mm": pen_mm = [x, y], tolerance_mm — where the machine's pen is at the end.
#pragma once

#include "kinds/expectation_kind.hpp"

namespace stepdance::sim {

struct PenPositionCheck {
  double x_mm = 0;
  double y_mm = 0;
  double tolerance_mm = 0.01;
};

const ExpectationKind& pen_position_expectation();

}  // namespace stepdance::sim
