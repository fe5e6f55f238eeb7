// Test controls of the Arduino backend hooks on the manual backend (host/hal_manual).
//
// This library defines arduino_backend::delay_us and arduino_backend::serial_stream for test
// executables that run sketches on hal_manual:
//  - delay_us(us) runs us / 40 whole frame ticks (hal_manual::run_frames, so the frame and
//    kilohertz ISRs fire as they would during a real delay()), then advances the clock by the
//    remaining us % 40 without a tick. Time advances by exactly us; sub-frame remainders of
//    separate calls never add up to a tick.
//  - every serial port is connected to an in-memory stream that a test can feed and read.
#pragma once

#include <stdint.h>

#include <string>

#include "arduino_backend.hpp"

namespace stepdance::arduino_manual {

/// Bytes a sketch wrote to a serial port since the last call (they are taken).
std::string take_serial_output(arduino_backend::SerialPortId port);
/// Queues bytes for the sketch to read from a serial port.
void feed_serial(arduino_backend::SerialPortId port, const std::string& bytes);
/// Connects (the default) or disconnects a port: disconnected, serial_stream() returns nullptr.
void set_serial_connected(arduino_backend::SerialPortId port, bool connected);
/// The most bytes a port holds before the test takes them (default: unlimited); when it is full,
/// the port refuses bytes and the sketch's writes wait (see HardwareSerial).
void set_serial_write_space(arduino_backend::SerialPortId port, size_t bytes);

/// Total microseconds passed to delay_us since reset, and the number of calls.
uint64_t delayed_us();
uint32_t delay_calls();

/// Empties and reconnects every port and zeroes the delay statistics. Does not touch hal_manual
/// or the Arduino API's own state (see reset_all()).
void reset();

/// The whole host board to power-on state: hal_manual::reset(start_us), reset() and
/// arduino::reset_state().
void reset_all(uint32_t start_us = 0);

}  // namespace stepdance::arduino_manual
