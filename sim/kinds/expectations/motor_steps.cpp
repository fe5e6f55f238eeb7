// Expectation kind "motor": motor = "board:A", steps = N — a stepper's final position in
// microsteps.
#include "kinds/expectations/motor_steps.hpp"

#include <optional>

#include "kinds/expectations/expectation_parts.hpp"
#include "models/stepper_driver.hpp"
#include "scenario/names.hpp"

namespace stepdance::sim {
namespace {

/// The stepper socket `text` names ("board:A"), reported at 'motor' if it is not one.
std::optional<scenario::PortRef> stepper_socket(scenario::TableReader& reader, const scenario::Scenario& scenario,
                                                const std::string& text) {
  const std::optional<scenario::SplitRef> split = scenario::split_ref(text);
  if (!split || split->rest.size() != 1 || split->rest[0] < 'A' || split->rest[0] > 'D') {
    reader.error("motor", "'motor' must look like \"board:A\" (a socket), got \"" + text + "\"");
    return std::nullopt;
  }
  const scenario::BoardConfig* board = scenario.board(split->board);
  if (board == nullptr) {
    reader.error("motor", "unknown board '" + split->board + "'");
    return std::nullopt;
  }
  const scenario::SocketConfig* socket = board->socket(split->rest[0]);
  if (socket == nullptr || socket->device != scenario::SocketDevice::kStepper) {
    reader.error("motor", "socket " + split->rest + " of board '" + board->name + "' holds no stepper");
    return std::nullopt;
  }
  return scenario::PortRef{board->name, split->rest[0]};
}

bool read(ExpectationReading& reading) {
  const auto text = reading.reader.string("motor");
  const auto steps = reading.reader.integer("steps", scenario::Need::kRequired);
  if (!text) return false;
  const auto motor = stepper_socket(reading.reader, reading.context.scenario, *text);
  if (!steps || !motor) return false;
  reading.settings = MotorStepsCheck{*motor, *steps};
  return true;
}

ExpectationResult check(const scenario::Expectation& expectation, const FinishedRun& run) {
  const auto& check = settings_of<MotorStepsCheck>(expectation);
  const std::string name = check.motor.board + ":" + check.motor.port;
  const StepperDriver* motor = run.stepper(check.motor.board, check.motor.port);
  if (motor == nullptr) return {false, "motor " + name + ": no stepper in that socket"};
  return compare("motor " + name + " steps", check.steps, motor->position_steps());
}

}  // namespace

const ExpectationKind& motor_steps_expectation() {
  static const ExpectationKind kind{"motor", {"steps"}, read, check};
  return kind;
}

}  // namespace stepdance::sim
