// Evaluation of [[expect]] entries: each is checked by its kind (kinds/expectation_kind.hpp)
// against the finished simulation, seen through FinishedRun.
#include "assembly/expectations.hpp"

#include "assembly/simulation.hpp"
#include "kinds/finished_run.hpp"

namespace stepdance::sim {
namespace {

std::string place(const scenario::Scenario& scenario, const scenario::Expectation& expectation) {
  return scenario.file + ":" + std::to_string(expectation.line) + ": ";
}

/// The simulation at its end, as the checks see it.
class SimulationRun : public FinishedRun {
 public:
  SimulationRun(const scenario::Scenario& scenario, const Simulation& simulation)
      : scenario_(scenario), simulation_(simulation) {}

  const scenario::Scenario& scenario() const override { return scenario_; }
  const StepperDriver* stepper(const std::string& board, char port) const override {
    return simulation_.stepper(board, port);
  }
  const Machine* machine() const override { return simulation_.machine(); }
  const SimDevice* device(const std::string& name) const override { return simulation_.device(name); }

  const PulseCounts* pulses(const scenario::PortLineRef& port) const override {
    const SimBoard* board = simulation_.board(port.board);
    if (board == nullptr) return nullptr;
    const uint8_t index = static_cast<uint8_t>(port.port - 'A');
    return port.output ? &board->ports().sent(index) : &board->ports().received(index);
  }

  std::optional<I2cLoopTiming> i2c_timing(const std::string& name) const override {
    const SimBoard* board = simulation_.board(name);
    if (board == nullptr) return std::nullopt;
    return I2cLoopTiming{board->i2c().timing().max_loop_pass_ns, board->i2c().timing().transfers};
  }

  std::optional<HostOutcome> host(const std::string& board) const override {
    const HostClient* client = simulation_.host_client(board);
    if (client == nullptr) return std::nullopt;
    return HostOutcome{&client->transcript(), client->completed(), client->failure()};
  }

 private:
  const scenario::Scenario& scenario_;
  const Simulation& simulation_;
};

}  // namespace

std::vector<ExpectationResult> evaluate_expectations(const scenario::Scenario& scenario, const Simulation& simulation) {
  const SimulationRun run(scenario, simulation);
  std::vector<ExpectationResult> results;
  for (const scenario::Expectation& expectation : scenario.expectations) {
    ExpectationResult result = expectation.kind->check(expectation, run);
    result.message = place(scenario, expectation) + result.message;
    results.push_back(std::move(result));
  }
  return results;
}

std::vector<ExpectationResult> unchecked_expectations(const scenario::Scenario& scenario, const std::string& reason) {
  std::vector<ExpectationResult> results;
  for (const scenario::Expectation& expectation : scenario.expectations) {
    results.push_back({false, place(scenario, expectation) + "not checked: " + reason, false});
  }
  return results;
}

}  // namespace stepdance::sim
