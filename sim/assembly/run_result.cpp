// run_result_json: the summary, the expectations and the stop of a finished run, as JSON text.
#include "assembly/run_result.hpp"

#include <nlohmann/json.hpp>

namespace stepdance::sim {

std::string run_result_json(const Simulation& simulation, const SimulationReport& report) {
  nlohmann::json expectations = nlohmann::json::array();
  for (const ExpectationResult& result : report.expectations) {
    expectations.push_back({{"met", result.met}, {"checked", result.checked}, {"message", result.message}});
  }
  nlohmann::json stopped = nullptr;
  if (report.sketch_stop) stopped = report.sketch_stop->message();
  const nlohmann::json result = {{"summary", nlohmann::json::parse(simulation.summary_text())},
                                 {"expectations", expectations},
                                 {"stopped", stopped}};
  return result.dump(2) + "\n";
}

}  // namespace stepdance::sim
