/* servo_pulse.c: step-count to hobby-servo pulse arithmetic (see servo_pulse.h). */
#include "servo_pulse.h"

int32_t servo_pulse_clamp_steps(const servo_pulse_settings* settings, int32_t steps) {
  if (steps > settings->top_limit_steps) {
    return settings->top_limit_steps;
  }
  if (steps < settings->bottom_limit_steps) {
    return settings->bottom_limit_steps;
  }
  return steps;
}

/* Width at zero steps, in us; signed so that out-of-range settings can be detected. */
static int32_t neutral_width_us(const servo_pulse_settings* settings) {
  return (int32_t)settings->midpoint_width_us + settings->width_offset_us;
}

uint16_t servo_pulse_width_us(const servo_pulse_settings* settings, int32_t steps) {
  return (uint16_t)(neutral_width_us(settings) + servo_pulse_clamp_steps(settings, steps));
}

uint16_t servo_pulse_period_us(const servo_pulse_settings* settings) {
  return (uint16_t)((int32_t)settings->period_us + settings->period_offset_us);
}

uint16_t servo_pulse_top_for_period_us(uint16_t period_us) { return (uint16_t)(period_us - 1u); }

uint16_t servo_pulse_compare_for_width_us(uint16_t width_us) { return (uint16_t)(width_us - 1u); }

bool servo_pulse_settings_valid(const servo_pulse_settings* settings) {
  /* 64-bit sums: the limits may be anything a build flag can hold. */
  const int64_t period_us = (int64_t)settings->period_us + settings->period_offset_us;
  const int64_t min_width_us = (int64_t)neutral_width_us(settings) + settings->bottom_limit_steps;
  const int64_t max_width_us = (int64_t)neutral_width_us(settings) + settings->top_limit_steps;

  return settings->bottom_limit_steps <= settings->top_limit_steps && period_us >= 2 && period_us <= UINT16_MAX &&
         min_width_us >= 1 && max_width_us < period_us;
}
