// Expectation kind "bounds_mm": bounds_mm = [x_min, y_min, x_max, y_max], tolerance_mm — the
// bounding box of every pen-down stroke, each edge within the tolerance.
#pragma once

#include "kinds/expectation_kind.hpp"

namespace stepdance::sim {

struct BoundsCheck {
  double bounds_mm[4] = {0, 0, 0, 0};
  double tolerance_mm = 0.01;
};

const ExpectationKind& bounds_expectation();

}  // namespace stepdance::sim
