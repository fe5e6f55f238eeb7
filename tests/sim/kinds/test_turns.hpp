// A test-only expectation kind, "test_turns": test_turns = "board:A", turns = T — the stepper in
// a socket turned T revolutions (its microsteps over microsteps × full steps a revolution), to
// within a thousandth of a turn. Its keys, reader, check and report line live here and nowhere
// else: registering it (ScopedKind<ExpectationRegistry>) is all the simulator needs.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

#include "kinds/expectation_kinds.hpp"
#include "kinds/scoped_kind.hpp"
#include "models/stepper_driver.hpp"
#include "scenario/names.hpp"

namespace stepdance::sim::test {

/// The socket, its microsteps a revolution (from the scenario), and the turns expected.
struct TestTurnsCheck {
  scenario::PortRef socket;
  int64_t steps_per_turn = 0;
  double turns = 0;
};

inline constexpr scenario::NumberRange kTestTurns{-1000, 1000, false, "turns"};
inline constexpr double kTestTurnsTolerance = 0.001;

inline bool read_test_turns(ExpectationReading& reading) {
  scenario::TableReader& reader = reading.reader;
  const auto text = reader.string("test_turns");
  const auto turns = reader.number("turns", kTestTurns, scenario::Need::kRequired);
  const auto split = text ? scenario::split_ref(*text) : std::nullopt;
  const scenario::BoardConfig* board = split ? reading.context.scenario.board(split->board) : nullptr;
  const scenario::SocketConfig* socket =
      board != nullptr && split->rest.size() == 1 ? board->socket(split->rest[0]) : nullptr;
  if (text && (socket == nullptr || socket->device != scenario::SocketDevice::kStepper)) {
    reader.error("test_turns", "'test_turns' must name a stepper socket \"board:A\", got \"" + *text + "\"");
    return false;
  }
  if (!turns || socket == nullptr) return false;
  reading.settings =
      TestTurnsCheck{{board->name, socket->port}, int64_t{socket->microsteps} * socket->full_steps_per_rev, *turns};
  return true;
}

inline ExpectationResult check_test_turns(const scenario::Expectation& expectation, const FinishedRun& run) {
  const TestTurnsCheck& check = *expectation.settings_as<TestTurnsCheck>();
  const StepperDriver* motor = run.stepper(check.socket.board, check.socket.port);
  if (motor == nullptr) return {false, "test_turns: no stepper"};
  const double turned = static_cast<double>(motor->position_steps()) / static_cast<double>(check.steps_per_turn);
  char text[160];
  std::snprintf(text, sizeof text, "motor %s:%c turned %.4f turns (expected %.4f)", check.socket.board.c_str(),
                check.socket.port, turned, check.turns);
  return {std::fabs(turned - check.turns) <= kTestTurnsTolerance, text};
}

inline const ExpectationKind& test_turns_kind() {
  static const ExpectationKind kind{"test_turns", {"turns"}, read_test_turns, check_test_turns};
  return kind;
}

}  // namespace stepdance::sim::test
