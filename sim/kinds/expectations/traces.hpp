// Expectation kind "traces": traces = "<five_bar_arm device>", offset_mm = [dx, dy],
// from_point = N, tolerance_mm — the drawing copies the arm's stylus path, both ways.
#pragma once

#include <cstdint>
#include <string>

#include "kinds/expectation_kind.hpp"

namespace stepdance::sim {

struct TracesCheck {
  /// The arm device, the shift from its coordinates to the page's, and the first path point that
  /// must be drawn (0 = path_mm[0]).
  std::string arm;
  double offset_mm[2] = {0, 0};
  int64_t from_point = 0;
  double tolerance_mm = 0.01;
};

const ExpectationKind& traces_expectation();

}  // namespace stepdance::sim
