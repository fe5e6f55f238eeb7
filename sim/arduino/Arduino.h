// The Arduino API on the host, for Stepdance sketches: the simulator force-includes this header
// into every sketch (-include Arduino.h), as the Arduino IDE does, so an .ino compiles unchanged.
//
// Everything is implemented over the HAL facade (stepdance/hal/hal.hpp) plus two backend hooks
// (arduino_backend.hpp), so the same API runs on the simulator and on the manual test backend.
// What is here: setup()/loop(), pin functions and constants, analogRead, millis/micros/delay,
// Print/Stream/String, Serial and friends, math helpers, random(), elapsedMillis/elapsedMicros.
// What is not: timers (IntervalTimer), PWM and tone — Stepdance owns the board's timers.
//
// Unlike the Arduino core, nothing here is a macro except F(): min, max, constrain, map, PI and
// the pin names are templates and constants, so standard headers included later still compile.
#pragma once

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "HardwareSerial.h"
#include "Print.h"
#include "Stream.h"
#include "WString.h"
#include "arduino_math.h"
#include "arduino_pins.h"
#include "arduino_time.h"
#include "elapsedMillis.h"

/// Arduino's byte and boolean types.
using byte = uint8_t;
using boolean = bool;

/// The sketch's entry points: setup() runs once after power-on, then loop() runs forever.
void setup();
void loop();
