// The Arduino API on the host, for Stepdance sketches: the simulator force-includes this header
// into every sketch (-include Arduino.h), as the Arduino IDE does, so an .ino compiles unchanged.
//
// Everything is implemented over the HAL facade (stepdance/hal/hal.hpp) plus two backend hooks
// (arduino_backend.hpp), so the same API runs on the simulator and on the manual test backend.
// What is here: setup()/loop(), pin functions and constants (digitalReadFast/digitalWriteFast
// too), analogRead, millis/micros/delay, Print/Stream/String, Serial and friends, math helpers,
// random(), elapsedMillis/elapsedMicros, IntervalTimer, float32_t/float64_t. SD.h and
// usb_names.h are there for the sketches that include them. What is not: PWM and tone.
//
// Unlike the Arduino core, nothing here is a macro except F() and Teensy's memory-placement
// attributes: min, max, constrain, map, PI and the pin names are templates and constants, so
// standard headers included later still compile.
#pragma once

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "HardwareSerial.h"
#include "IntervalTimer.h"
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

/// The CMSIS DSP names Teensyduino sketches use for single and double precision (arm_math.h).
using float32_t = float;
using float64_t = double;

/// Teensy's memory-placement attributes (code in ITCM, data in RAM2, external RAM, constants in
/// flash). Memory is flat on the host, so they expand to nothing.
#define FASTRUN
#define FLASHMEM
#define PROGMEM
#define DMAMEM
#define EXTMEM
