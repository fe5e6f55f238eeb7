// The built-in expectation kinds, one line each, in the order messages list them
// ("an [[expect]] needs one check: motor, pen_mm, …").
#include "kinds/expectation_kinds.hpp"
#include "kinds/expectations/bounds.hpp"
#include "kinds/expectations/cable_counts.hpp"
#include "kinds/expectations/drawn_length.hpp"
#include "kinds/expectations/extrusion_ratio.hpp"
#include "kinds/expectations/host.hpp"
#include "kinds/expectations/i2c_loop_time.hpp"
#include "kinds/expectations/motor_steps.hpp"
#include "kinds/expectations/pen_position.hpp"
#include "kinds/expectations/port_pulses.hpp"
#include "kinds/expectations/rejected.hpp"
#include "kinds/expectations/screen_text.hpp"
#include "kinds/expectations/strokes.hpp"
#include "kinds/expectations/traces.hpp"
#include "kinds/expectations/z_position.hpp"

namespace stepdance::sim {

std::vector<const ExpectationKind*> builtin_expectation_kinds() {
  return {
      &motor_steps_expectation(),  &pen_position_expectation(),  &strokes_expectation(),         &bounds_expectation(),
      &drawn_length_expectation(), &z_position_expectation(),    &extrusion_ratio_expectation(), &traces_expectation(),
      &port_pulses_expectation(),  &cable_counts_expectation(),  &rejected_expectation(),        &host_expectation(),
      &screen_text_expectation(),  &i2c_loop_time_expectation(),
  };
}

}  // namespace stepdance::sim
