/* servo_pwm.c: Timer1 fast PWM (mode 14, TOP = ICR1, 1 us ticks) producing the servo pulse on OC1B. */
#include "servo_pwm.h"

#include <avr/io.h> /* Timer1 registers, DDRA */

#include "board_pins.h" /* SERVO_PIN_BIT */

#if F_CPU != 8000000UL
#error "servo_pwm assumes F_CPU = 8 MHz: prescaler 8 then gives 1 us per Timer1 tick"
#endif

void servo_pwm_start(uint16_t top_ticks, uint16_t compare_ticks) {
  DDRA |= _BV(SERVO_PIN_BIT);
  /* TOP and the first width are in place before the clock starts. */
  ICR1 = top_ticks;
  OCR1B = compare_ticks;
  /* COM1B1: set OC1B at BOTTOM, clear on match. WGM13:10 = 1110: fast PWM, TOP = ICR1. CS11: clk/8. */
  TCCR1A = _BV(COM1B1) | _BV(WGM11);
  TCCR1B = _BV(WGM13) | _BV(WGM12) | _BV(CS11);
}

bool servo_pwm_period_elapsed(void) { return (TIFR1 & _BV(TOV1)) != 0; }

void servo_pwm_acknowledge_period(void) { TIFR1 = _BV(TOV1); }

void servo_pwm_set_compare(uint16_t compare_ticks) { OCR1B = compare_ticks; }
