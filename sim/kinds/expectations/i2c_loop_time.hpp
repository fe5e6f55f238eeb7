// Expectation kind "i2c_loop_pass_max_us": i2c_loop_pass_max_us = bound (µs, > 0),
// board = "<board>" — no loop pass of the board spent more wire time than that in I2C transfers.
#pragma once

#include <string>

#include "kinds/expectation_kind.hpp"

namespace stepdance::sim {

struct I2cLoopTimeCheck {
  std::string board;
  double max_us = 0;
};

const ExpectationKind& i2c_loop_time_expectation();

}  // namespace stepdance::sim
