// Expectation kind "z_mm": z_mm = z, tolerance_mm — the machine's final z (a cartesian machine
// with a 'z' socket).
#pragma once

#include "kinds/expectation_kind.hpp"

namespace stepdance::sim {

struct ZPositionCheck {
  double z_mm = 0;
  double tolerance_mm = 0.01;
};

const ExpectationKind& z_position_expectation();

}  // namespace stepdance::sim
