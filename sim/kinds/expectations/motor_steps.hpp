// Expectation kind "motor": motor = "board:A", steps = N — a stepper's final position in
// microsteps.
#pragma once

#include <cstdint>

#include "kinds/expectation_kind.hpp"

namespace stepdance::sim {

struct MotorStepsCheck {
  scenario::PortRef motor;
  int64_t steps = 0;
};

const ExpectationKind& motor_steps_expectation();

}  // namespace stepdance::sim
