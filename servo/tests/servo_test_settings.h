// servo_test_settings.h: the two shipped servo builds as servo_pulse_settings, from the firmware's defaults.
#pragma once

#include "servo_pulse.h"
#include "servo_settings.h"

namespace servo_test {

// The default (90-degree) build: every setting as in servo_settings.h.
inline servo_pulse_settings settings_90deg() {
  return servo_pulse_settings{PULSE_PERIOD_US,       PULSE_PERIOD_OFFSET,
                              PULSE_WIDTH_OFFSET,    SERVO_MIDPOINT_PULSE_WIDTH_US,
                              SERVO_TOP_LIMIT_STEPS, SERVO_BOTTOM_LIMIT_STEPS};
}

// The 180-degree build: the same, with a window of +/-750 steps.
inline servo_pulse_settings settings_180deg() {
  servo_pulse_settings settings = settings_90deg();
  settings.top_limit_steps = 750;
  settings.bottom_limit_steps = -750;
  return settings;
}

}  // namespace servo_test
