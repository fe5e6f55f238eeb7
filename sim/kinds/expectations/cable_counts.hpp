// Expectation kind "cable_counts_match": cable_counts_match = true — every cable's receiving port
// accepted exactly the pulses (per signal and direction) its sending port put on the wire.
#pragma once

#include "kinds/expectation_kind.hpp"

namespace stepdance::sim {

struct CableCountsCheck {};

const ExpectationKind& cable_counts_expectation();

}  // namespace stepdance::sim
