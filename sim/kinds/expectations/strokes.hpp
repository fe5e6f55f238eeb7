// Expectation kind "strokes": strokes = N — how many pen-down strokes the machine drew.
#pragma once

#include <cstdint>

#include "kinds/expectation_kind.hpp"

namespace stepdance::sim {

struct StrokesCheck {
  int64_t strokes = 0;
};

const ExpectationKind& strokes_expectation();

}  // namespace stepdance::sim
