// Internal: the reset function of each part of the host Arduino API, called by reset_state().
#pragma once

#include "IntervalTimer.h"

namespace stepdance::arduino::internal {

/// Forgets the millis()/micros() wrap tracking (arduino_time.cpp).
void reset_time_state();
/// Forgets the pins analogRead() started and the analog resolution (arduino_pins.cpp).
void reset_pin_state();
/// Restores the random() generator's power-on seed (arduino_math.cpp).
void reset_random_state();
/// Drops peeked bytes and restores the timeout of every serial port (HardwareSerial.cpp).
void reset_serial_state();
/// Stops every IntervalTimer and restarts the timers' clock (interval_timer.cpp).
void reset_interval_timer_state();
/// IntervalTimer's table of four running timers, keyed by the timer object (interval_timer.cpp).
bool start_interval_timer(const IntervalTimer* owner, IntervalTimer::Callback callback, double period_us);
void update_interval_timer(const IntervalTimer* owner, double period_us);
void stop_interval_timer(const IntervalTimer* owner);

}  // namespace stepdance::arduino::internal
