/* servo_pulse.h: step-count to hobby-servo pulse arithmetic, shared by the ATtiny84 firmware,
 * the host unit tests and the simulator's servo-board model. Pure C99, no hardware headers. */
#ifndef STEPDANCE_SERVO_PULSE_H
#define STEPDANCE_SERVO_PULSE_H

#include <stdbool.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Timing model (Timer1 at 1 tick = 1 us, fast PWM mode 14, TOP = ICR1, OC1B non-inverting):
 *   - the counter runs 0..TOP, so one period lasts TOP + 1 ticks;
 *   - OC1B is set at BOTTOM and cleared on the tick after TCNT1 == OCR1B, so the pulse is
 *     high for OCR1B + 1 ticks.
 * Hence ICR1 = period_us - 1 and OCR1B = width_us - 1. */

/* Build-time settings of one servo board. All values are in microseconds or steps. */
typedef struct servo_pulse_settings {
  uint16_t period_us;         /* nominal time between pulse starts (PULSE_PERIOD_US) */
  int16_t period_offset_us;   /* trim added to the period for RC-clock error (PULSE_PERIOD_OFFSET) */
  int16_t width_offset_us;    /* trim added to every width (PULSE_WIDTH_OFFSET) */
  uint16_t midpoint_width_us; /* width at zero steps before the trim (SERVO_MIDPOINT_PULSE_WIDTH_US) */
  int32_t top_limit_steps;    /* highest step count that still moves the servo (SERVO_TOP_LIMIT_STEPS) */
  int32_t bottom_limit_steps; /* lowest step count that still moves the servo (SERVO_BOTTOM_LIMIT_STEPS) */
} servo_pulse_settings;

/* Returns steps limited to [bottom_limit_steps, top_limit_steps]. */
int32_t servo_pulse_clamp_steps(const servo_pulse_settings* settings, int32_t steps);

/* Returns the pulse width in us for a step count: midpoint + width offset + clamped steps
 * (1 step = 1 us). Precondition: servo_pulse_settings_valid(settings). */
uint16_t servo_pulse_width_us(const servo_pulse_settings* settings, int32_t steps);

/* Returns the pulse period in us: period + period offset. */
uint16_t servo_pulse_period_us(const servo_pulse_settings* settings);

/* Returns the Timer1 TOP (ICR1) value giving a period of period_us 1-us ticks.
 * Precondition: period_us >= 2. */
uint16_t servo_pulse_top_for_period_us(uint16_t period_us);

/* Returns the OCR1B value giving a high pulse of width_us 1-us ticks. Precondition: width_us >= 1. */
uint16_t servo_pulse_compare_for_width_us(uint16_t width_us);

/* True when every width in the step window is at least 1 us and ends before the period does,
 * the period lies in 2..65535 us (Timer1 and uint16_t), and bottom_limit_steps <= top_limit_steps. */
bool servo_pulse_settings_valid(const servo_pulse_settings* settings);

#ifdef __cplusplus
}
#endif

#endif /* STEPDANCE_SERVO_PULSE_H */
