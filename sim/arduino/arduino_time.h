// Arduino time functions on the host: millis(), micros(), delay(), delayMicroseconds(), yield().
#pragma once

#include <stdint.h>

/// Microseconds since the board started, wrapping at 2^32 (every 71.6 minutes), read from
/// hal::micros_now(). Compare two readings with unsigned subtraction held in 32 bits:
/// `(uint32_t)(micros() - start)`. Note: on a Teensy `unsigned long` is 32 bits; on a 64-bit host
/// it is 64, so a sketch that keeps micros() in an `unsigned long` sees the wrap as a jump.
/// Context: any (on the host, interrupts and the loop share one thread).
uint32_t micros();

/// Milliseconds since the board started, wrapping at 2^32 (every 49.7 days), exact across the
/// microsecond counter's wraps as long as millis() or micros() is called at least once every
/// 71 minutes of board time. Context: loop (it updates the wrap tracking).
uint32_t millis();

/// Waits `ms` milliseconds of board time; frames, timers and devices keep running meanwhile
/// (through arduino_backend::delay_us). Context: loop.
void delay(uint32_t ms);

/// Waits `us` microseconds of board time, as delay() does. Context: loop.
void delayMicroseconds(uint32_t us);

/// Called by sketches that busy-wait. Does nothing on the host: the Teensy core uses it to
/// service serial events, which the simulator delivers by itself. Use delay() to let board
/// time pass. Context: loop.
void yield();
