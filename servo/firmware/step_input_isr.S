/* step_input_isr.S: the STEP pin-change interrupt, in assembly so that STEP is sampled on the
 * interrupt's first instruction (a C handler saves registers first and misses 2 us pulses). */
#include <avr/io.h>     /* PINA, SREG, _SFR_IO_ADDR */

#include "board_pins.h" /* STEP_PIN_BIT, DIR_PIN_BIT */

    .section .text.step_input_isr, "ax", @progbits
    .global PCINT0_vect
    .type PCINT0_vect, @function

/* Runs on both STEP edges. STEP high means the rising edge: add +1 (DIR high) or -1 (DIR low) to
 * step_input_position_steps, then bump step_input_position_sequence. STEP low means the falling
 * edge, which returns at once; sbis and reti leave every register and SREG untouched. */
PCINT0_vect:
    sbis _SFR_IO_ADDR(PINA), STEP_PIN_BIT
    reti
    push r24
    in r24, _SFR_IO_ADDR(PINA)  /* DIR, read next: it must be valid ~2 us after the rising edge */
    push r25
    in r25, _SFR_IO_ADDR(SREG)
    push r25
    bst r24, DIR_PIN_BIT        /* T = DIR (SREG is saved, so T is ours) */
    push r26
    push r27
    lds r24, step_input_position_steps
    lds r25, step_input_position_steps + 1
    lds r26, step_input_position_steps + 2
    lds r27, step_input_position_steps + 3
    brts 1f
    subi r24, 1                 /* DIR low: subtract 1 */
    sbci r25, 0
    sbci r26, 0
    sbci r27, 0
    rjmp 2f
1:  subi r24, 0xFF              /* DIR high: subtract -1 */
    sbci r25, 0xFF
    sbci r26, 0xFF
    sbci r27, 0xFF
2:  sts step_input_position_steps, r24
    sts step_input_position_steps + 1, r25
    sts step_input_position_steps + 2, r26
    sts step_input_position_steps + 3, r27
    lds r24, step_input_position_sequence
    inc r24
    sts step_input_position_sequence, r24
    pop r27
    pop r26
    pop r25
    out _SFR_IO_ADDR(SREG), r25
    pop r25
    pop r24
    reti
    .size PCINT0_vect, . - PCINT0_vect
