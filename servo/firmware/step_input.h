/* step_input.h: counts STEP/DIR pulses into a signed step position. */
#ifndef STEPDANCE_SERVO_STEP_INPUT_H
#define STEPDANCE_SERVO_STEP_INPUT_H

#include <stdint.h>

/* Makes STEP and DIR inputs and enables the STEP pin-change interrupt. The position starts at 0.
 * Call once, before sei(). */
void step_input_start(void);

/* Returns the step position (+1 per STEP rising edge with DIR high, -1 with DIR low), read as one
 * consistent 32-bit value without disabling interrupts. Call from the main loop only. */
int32_t step_input_read_steps(void);

#endif /* STEPDANCE_SERVO_STEP_INPUT_H */
