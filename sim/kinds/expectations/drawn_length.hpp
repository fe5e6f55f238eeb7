// Expectation kind "drawn_mm": drawn_mm = length, tolerance_mm — the total pen-down path length.
#pragma once

#include "kinds/expectation_kind.hpp"

namespace stepdance::sim {

struct DrawnLengthCheck {
  double drawn_mm = 0;
  double tolerance_mm = 0.01;
};

const ExpectationKind& drawn_length_expectation();

}  // namespace stepdance::sim
