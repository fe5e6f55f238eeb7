// Resets every part of the host Arduino API to power-on state (see arduino_backend.hpp).
#include "arduino_state.hpp"

#include "arduino_backend.hpp"

namespace stepdance::arduino {

void reset_state() {
  internal::reset_time_state();
  internal::reset_pin_state();
  internal::reset_random_state();
  internal::reset_serial_state();
  internal::reset_interval_timer_state();
}

}  // namespace stepdance::arduino
