/* board_pins.h: where STEP, DIR and the servo output sit on the servo driver's ATtiny84 (all port A). */
#ifndef STEPDANCE_SERVO_BOARD_PINS_H
#define STEPDANCE_SERVO_BOARD_PINS_H

#define STEP_PIN_BIT 7  /* PA7 / PCINT7: STEP input, pin-change interrupt */
#define DIR_PIN_BIT 6   /* PA6: DIR input, high = +1 step, low = -1 step */
#define SERVO_PIN_BIT 5 /* PA5 / OC1B: servo pulse output */

#endif /* STEPDANCE_SERVO_BOARD_PINS_H */
