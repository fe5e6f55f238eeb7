/* main.c: servo driver firmware: STEP/DIR in, one hobby-servo pulse per period out. */
#include <avr/interrupt.h> /* sei */

#include "servo_pulse.h"    /* servo_pulse_settings, width and register arithmetic */
#include "servo_pwm.h"      /* servo_pwm_* */
#include "servo_settings.h" /* PULSE_PERIOD_US ... SERVO_MIDPOINT_PULSE_WIDTH_US */
#include "step_input.h"     /* step_input_* */

static const servo_pulse_settings settings = {
    .period_us = PULSE_PERIOD_US,
    .period_offset_us = PULSE_PERIOD_OFFSET,
    .width_offset_us = PULSE_WIDTH_OFFSET,
    .midpoint_width_us = SERVO_MIDPOINT_PULSE_WIDTH_US,
    .top_limit_steps = SERVO_TOP_LIMIT_STEPS,
    .bottom_limit_steps = SERVO_BOTTOM_LIMIT_STEPS,
};

/* OCR1B value for the current step position. */
static uint16_t compare_for_steps(int32_t steps) {
  return servo_pulse_compare_for_width_us(servo_pulse_width_us(&settings, steps));
}

int main(void) {
  step_input_start();
  servo_pwm_start(servo_pulse_top_for_period_us(servo_pulse_period_us(&settings)), compare_for_steps(0));
  sei();

  /* Once per period, right after TOP: sample the position and queue the next pulse's width. */
  for (;;) {
    if (servo_pwm_period_elapsed()) {
      servo_pwm_acknowledge_period();
      servo_pwm_set_compare(compare_for_steps(step_input_read_steps()));
    }
  }
}
