/* step_input.c: STEP/DIR set-up and the step position kept by the interrupt in step_input_isr.S. */
#include "step_input.h"

#include <avr/io.h> /* DDRA, PCMSK0, GIFR, GIMSK */

#include "board_pins.h" /* STEP_PIN_BIT, DIR_PIN_BIT */

/* Step position. Written only by the STEP interrupt; external linkage so that the interrupt and
 * test harnesses can find it by name. Never saturates (see docs/servo-driver.md). */
volatile int32_t step_input_position_steps;

/* Incremented by the STEP interrupt after every position change; lets the main loop read the
 * position consistently without disabling interrupts. */
volatile uint8_t step_input_position_sequence;

void step_input_start(void) {
  DDRA &= (uint8_t) ~(_BV(STEP_PIN_BIT) | _BV(DIR_PIN_BIT));
  PCMSK0 = _BV(STEP_PIN_BIT);
  GIFR = _BV(PCIF0);
  GIMSK |= _BV(PCIE0);
}

/* A sequence-checked read: if the interrupt ran while the four bytes were copied, the sequence
 * differs and the copy is taken again. Interrupts stay enabled, so a STEP edge is never delayed. */
int32_t step_input_read_steps(void) {
  uint8_t sequence;
  int32_t steps;
  do {
    sequence = step_input_position_sequence;
    steps = step_input_position_steps;
  } while (sequence != step_input_position_sequence);
  return steps;
}
