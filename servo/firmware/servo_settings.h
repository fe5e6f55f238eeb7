/* servo_settings.h: build-time settings of the servo driver firmware; override any with -DNAME=value. */
#ifndef STEPDANCE_SERVO_SETTINGS_H
#define STEPDANCE_SERVO_SETTINGS_H

/* Nominal time between pulse starts, us. */
#ifndef PULSE_PERIOD_US
#define PULSE_PERIOD_US 24000
#endif

/* Trim added to the period, us; compensates the internal RC oscillator's error. */
#ifndef PULSE_PERIOD_OFFSET
#define PULSE_PERIOD_OFFSET 850
#endif

/* Trim added to every pulse width, us; compensates the internal RC oscillator's error. */
#ifndef PULSE_WIDTH_OFFSET
#define PULSE_WIDTH_OFFSET 40
#endif

/* Highest step count that still moves the servo (1 step = 1 us of width); 750 for a 180-degree build. */
#ifndef SERVO_TOP_LIMIT_STEPS
#define SERVO_TOP_LIMIT_STEPS 500
#endif

/* Lowest step count that still moves the servo; -750 for a 180-degree build. */
#ifndef SERVO_BOTTOM_LIMIT_STEPS
#define SERVO_BOTTOM_LIMIT_STEPS -500
#endif

/* Pulse width at zero steps before PULSE_WIDTH_OFFSET, us. */
#ifndef SERVO_MIDPOINT_PULSE_WIDTH_US
#define SERVO_MIDPOINT_PULSE_WIDTH_US 1500
#endif

/* The same checks as servo_pulse_settings_valid(), made at build time. */
#if (PULSE_PERIOD_US + PULSE_PERIOD_OFFSET) < 2 || (PULSE_PERIOD_US + PULSE_PERIOD_OFFSET) > 65535
#error "PULSE_PERIOD_US + PULSE_PERIOD_OFFSET must lie in 2..65535 (Timer1 is 16 bits)"
#endif
#if SERVO_BOTTOM_LIMIT_STEPS > SERVO_TOP_LIMIT_STEPS
#error "SERVO_BOTTOM_LIMIT_STEPS must not exceed SERVO_TOP_LIMIT_STEPS"
#endif
#if (SERVO_MIDPOINT_PULSE_WIDTH_US + PULSE_WIDTH_OFFSET + SERVO_BOTTOM_LIMIT_STEPS) < 1
#error "the narrowest pulse must be at least 1 us"
#endif
#if (SERVO_MIDPOINT_PULSE_WIDTH_US + PULSE_WIDTH_OFFSET + SERVO_TOP_LIMIT_STEPS) >= \
    (PULSE_PERIOD_US + PULSE_PERIOD_OFFSET)
#error "the widest pulse must end before the period does"
#endif

#endif /* STEPDANCE_SERVO_SETTINGS_H */
