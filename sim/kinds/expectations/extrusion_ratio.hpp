// Expectation kind "extruded_per_mm": extruded_per_mm = ratio, relative_tolerance (default 0.01)
// — the extruder's advance per mm of pen-down (extruding) path (a cartesian machine with an 'e'
// socket).
#pragma once

#include "kinds/expectation_kind.hpp"

namespace stepdance::sim {

struct ExtrusionRatioCheck {
  double extruded_per_mm = 0;
  double relative_tolerance = 0.01;  ///< 0.01 = 1 %
};

const ExpectationKind& extrusion_ratio_expectation();

}  // namespace stepdance::sim
