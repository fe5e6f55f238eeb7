// StepperDriver: microstep counting, enable handling and rotation.
#include "models/stepper_driver.hpp"

namespace stepdance::sim {

StepperDriver::StepperDriver(const StepperDriverSettings& settings)
    : microsteps_(valid_microsteps(settings.microsteps) ? settings.microsteps : 16),
      full_steps_per_rev_(settings.full_steps_per_rev > 0 ? settings.full_steps_per_rev : 200),
      enabled_(settings.enabled),
      reversed_(settings.reversed) {}

bool StepperDriver::valid_microsteps(int microsteps) {
  return microsteps >= 1 && microsteps <= kFinestMicrosteps && (microsteps & (microsteps - 1)) == 0;
}

void StepperDriver::on_step_rising(SimTime time, bool dir_high) {
  if (!enabled_) {
    ++ignored_steps_;
    return;
  }
  const int64_t sign = (dir_high != reversed_) ? 1 : -1;
  position_steps_ += sign;
  rotation_64ths_ += sign * (kFinestMicrosteps / microsteps_);
  if (dir_high) {
    ++forward_steps_;
  } else {
    ++reverse_steps_;
  }
  last_step_time_ = time;
}

void StepperDriver::set_enabled(bool enabled) { enabled_ = enabled; }

bool StepperDriver::set_microsteps(int microsteps) {
  if (!valid_microsteps(microsteps)) return false;
  microsteps_ = microsteps;
  return true;
}

double StepperDriver::revolutions() const {
  return static_cast<double>(rotation_64ths_) / (static_cast<double>(kFinestMicrosteps) * full_steps_per_rev_);
}

}  // namespace stepdance::sim
