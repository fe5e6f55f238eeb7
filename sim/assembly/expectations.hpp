// The scenario's [[expect]] checks, evaluated against a finished simulation.
#pragma once

#include <string>
#include <vector>

#include "scenario/scenario.hpp"

namespace stepdance::sim {

class Simulation;

/// The outcome of one [[expect]] entry.
struct ExpectationResult {
  bool met = false;
  /// `file:line: what was expected, and what happened` (also when met, for a report).
  std::string message;
  /// False when the run was stopped before its end and nothing was compared (never met then).
  bool checked = true;
};

/// Checks every expectation of `scenario` against the state of `simulation` at its end.
std::vector<ExpectationResult> evaluate_expectations(const scenario::Scenario& scenario, const Simulation& simulation);
/// Every expectation of `scenario` as not checked, for `reason` (the run did not reach its end).
std::vector<ExpectationResult> unchecked_expectations(const scenario::Scenario& scenario, const std::string& reason);

}  // namespace stepdance::sim
