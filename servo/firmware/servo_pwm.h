/* servo_pwm.h: Timer1 fast PWM (mode 14, TOP = ICR1, 1 us ticks) producing the servo pulse on OC1B. */
#ifndef STEPDANCE_SERVO_PWM_H
#define STEPDANCE_SERVO_PWM_H

#include <stdbool.h>
#include <stdint.h>

/* Starts the pulse train: period top_ticks + 1 us, first pulse compare_ticks + 1 us wide.
 * Requires F_CPU = 8 MHz (prescaler 8 gives 1 us ticks). */
void servo_pwm_start(uint16_t top_ticks, uint16_t compare_ticks);

/* True once the counter has reached TOP since the last servo_pwm_acknowledge_period(). */
bool servo_pwm_period_elapsed(void);

/* Clears the period flag tested by servo_pwm_period_elapsed(). */
void servo_pwm_acknowledge_period(void);

/* Sets OCR1B; the hardware latches it at the next BOTTOM, so a pulse never changes width midway.
 * Call from the main loop only (uses the Timer1 TEMP register). */
void servo_pwm_set_compare(uint16_t compare_ticks);

#endif /* STEPDANCE_SERVO_PWM_H */
