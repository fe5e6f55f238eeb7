// Expectation kind "rejected": rejected = N, port = "board:IN_A" — the pulses an input port
// refused (too short or too long).
#pragma once

#include <cstdint>

#include "kinds/expectation_kind.hpp"

namespace stepdance::sim {

struct RejectedCheck {
  scenario::PortLineRef port;
  int64_t rejected = 0;
};

const ExpectationKind& rejected_expectation();

}  // namespace stepdance::sim
