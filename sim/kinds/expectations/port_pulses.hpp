// Expectation kind "port": port = "board:OUT_A" (or IN_A), axis = "X", forward = N, reverse = N —
// the pulses of one signal a port sent or accepted, per direction.
#pragma once

#include <cstdint>
#include <optional>

#include "kinds/expectation_kind.hpp"

namespace stepdance::sim {

struct PortPulsesCheck {
  scenario::PortLineRef port;
  int signal = 0;  ///< 0..5 = X, Y, R, T, Z, E
  std::optional<int64_t> forward;
  std::optional<int64_t> reverse;
};

const ExpectationKind& port_pulses_expectation();

}  // namespace stepdance::sim
