// A finished run's result as one JSON document: the summary and every expectation's outcome.
#pragma once

#include <string>

#include "assembly/simulation.hpp"

namespace stepdance::sim {

/// The result of a finished run, the same text whichever front end ran it (`stepdance sim
/// --result-json`, the WebAssembly build): {"summary": the summary JSON without its wall time
/// (step counts per motor, pen position, strokes, …), "expectations": [{"met", "checked",
/// "message"} in scenario order], "stopped": the stopped sketch's message or null}. No wall
/// time or other host-dependent figure, so two builds of one scenario can be compared byte for
/// byte. Context: loop, after `simulation.finish()` returned `report`.
std::string run_result_json(const Simulation& simulation, const SimulationReport& report);

}  // namespace stepdance::sim
