// The scenario's [[expect]] checks, evaluated against a finished simulation.
#pragma once

#include <string>
#include <vector>

#include "kinds/expectation_kind.hpp"
#include "scenario/scenario.hpp"

namespace stepdance::sim {

class Simulation;

/// Checks every expectation of `scenario` against the state of `simulation` at its end.
std::vector<ExpectationResult> evaluate_expectations(const scenario::Scenario& scenario, const Simulation& simulation);
/// Every expectation of `scenario` as not checked, for `reason` (the run did not reach its end).
std::vector<ExpectationResult> unchecked_expectations(const scenario::Scenario& scenario, const std::string& reason);

}  // namespace stepdance::sim
