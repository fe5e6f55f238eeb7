// The hooks the host Arduino API needs from whichever backend runs the sketch (simulator, tests).
//
// Everything else the Arduino API does goes through the HAL facade (stepdance/hal/hal.hpp). The
// facade has no notion of "the sketch waits" or of serial ports besides the console, so the
// backend that runs the sketch defines these functions as well, exactly once per board:
//   - the simulator's board runtime (sim/board), inside each board's shared object;
//   - src/stepdance/platform/manual/arduino_manual.cpp for tests on the manual backend.
#pragma once

#include <stdint.h>

#include "stepdance/core/byte_stream.hpp"

namespace stepdance::arduino_backend {

/// Lets `us` microseconds of board time pass while the sketch waits inside an Arduino call:
/// delay(), delayMicroseconds(), a Stream read that waits for its timeout, a serial write that
/// waits for room, analogRead() waiting for a pin's first conversion.
///
/// Contract:
///  - Context: loop only (setup(), loop() and the callbacks dance_loop() runs). Never called
///    from an ISR.
///  - On return, hal::micros_now() reads exactly `us` later than on entry (modulo 2^32).
///  - While the time passes, everything that would happen on the real board happens: the frame
///    and kilohertz timers fire, input ports capture pulses, devices and other boards move on,
///    bytes arrive on serial streams. A real board busy-waits in delay() while its interrupts
///    preempt it; the backend must reproduce that.
///  - setup() and loop() are not re-entered, and no Arduino API function is called back.
///  - us == 0 returns at once; whether pending events run first is the backend's choice.
void delay_us(uint32_t us);

/// Serial ports other than `Serial` (which is always hal::console()).
enum class SerialPortId : uint8_t {
  kUsb1 = 0,  ///< SerialUSB1: second port of the Teensy "Dual Serial" USB type
  kUsb2 = 1,  ///< SerialUSB2: third port of "Triple Serial"
  kUart1,     ///< Serial1 .. Serial8: the Teensy 4.1 hardware UARTs
  kUart2,
  kUart3,
  kUart4,
  kUart5,
  kUart6,
  kUart7,
  kUart8,
};
/// Number of SerialPortId values.
constexpr uint8_t kSerialPortCount = 10;

/// The byte stream behind one serial port, or nullptr when nothing is connected to it. With
/// nullptr the port discards what the sketch writes (reporting it as written) and never has
/// bytes to read. Asked on every access, so a backend may connect a port at any time.
/// Context: loop.
ByteStream* serial_stream(SerialPortId port);

}  // namespace stepdance::arduino_backend

namespace stepdance::arduino {

/// Forgets the Arduino API's own state: the millis()/micros() wrap tracking, bytes peeked but
/// not read on every serial port, the pins analogRead() started, the analog resolution, the
/// random() generator, every Stream timeout and every IntervalTimer. Defined by the Arduino
/// API library (not by the backend); a backend calls it when it restarts a board in the same process, and tests call it
/// after resetting the manual backend's clock. Context: loop.
void reset_state();

}  // namespace stepdance::arduino
