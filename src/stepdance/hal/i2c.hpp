// I2C on the board's QWIIC connectors, as the core sees it: one transfer at a time per bus,
// started and polled from the loop, never from the frame.
//
// Part of the HAL facade (see hal.hpp). A backend defines these functions:
//   - platform/teensy/i2c_wire.cpp   (Teensyduino Wire / Wire1: QWIIC0 / QWIIC1)
//   - platform/manual/i2c_manual.cpp (unit tests: a scripted bus)
//   - platform/sim/sim_i2c.cpp       (the simulator: device models by address, 400 kHz timing)
// A transfer may occupy the loop for at most its own time on the wire (the Teensy backend uses
// Teensyduino's blocking Wire; the simulator models exactly that), so callers bound the loop's
// time on the bus by bounding the size of each transfer (kI2cMaxTransferBytes) and starting at
// most one per loop pass (QwiicBus does both).
#pragma once

#include <stdint.h>

#include "stepdance/core/status.hpp"

namespace stepdance::hal {

/// Buses: QWIIC0 (user accessories, Teensy Wire) and QWIIC1 (the board-mounted display and
/// knob, Teensy Wire1).
constexpr uint8_t kI2cBusCount = 2;
/// Most bytes one transfer may write, and most it may read.
constexpr uint16_t kI2cMaxTransferBytes = 40;
/// The standard fast-mode clock the QWIIC devices run at (Hz).
constexpr uint32_t kI2cFastModeHz = 400000;

/// How a transfer ended.
enum class I2cResult : uint8_t {
  kIdle = 0,     ///< nothing was started on the bus since the last result was taken
  kPending,      ///< the transfer is still on the wire
  kOk,           ///< every byte was acknowledged and every read byte received
  kAddressNack,  ///< no device answered the address (missing or unpowered)
  kDataNack,     ///< the device refused a written byte
  kBusError,     ///< arbitration lost, a line held low, or another bus fault
  kTimeout,      ///< the transfer did not finish within the backend's time limit
};

/// A short, stable name for a result ("address nack", …; never null). Context: any.
const char* to_string(I2cResult result);

/// One transfer: write `write_length` bytes to the 7-bit `address`, then, if read_length > 0,
/// a repeated start and read `read_length` bytes. Either part may be empty (both empty: an
/// address probe). The buffers must stay valid until i2c_poll() returns a final result.
struct I2cTransfer {
  uint8_t address = 0;
  const uint8_t* write = nullptr;
  uint16_t write_length = 0;
  uint8_t* read = nullptr;
  uint16_t read_length = 0;
};

/// Claims bus `bus` (0 = QWIIC0, 1 = QWIIC1) at `clock_hz` (100 kHz..1 MHz). kNoSuchPin if the
/// board lacks the bus, kBadArgument for a clock out of range; calling it again changes the
/// clock. Context: loop.
Status i2c_begin(uint8_t bus, uint32_t clock_hz);
/// Starts `transfer` on a begun bus. kBusy while the previous transfer is still pending,
/// kBadArgument for an address above 0x7F or a part longer than kI2cMaxTransferBytes,
/// kNotStarted if the bus was not begun. Context: loop.
Status i2c_start(uint8_t bus, const I2cTransfer& transfer);
/// The state of the bus's latest transfer: kPending while it runs, then its final result,
/// returned once (later calls return kIdle until the next start). Context: loop.
I2cResult i2c_poll(uint8_t bus);

// ---- Shared by the backends -------------------------------------------------------------------

/// The checks every backend's i2c_start() makes: kNotStarted for a bus out of range or not
/// begun, kBadArgument for an address above 0x7F or an oversized part. Context: any.
inline Status i2c_check_start(uint8_t bus, const bool (&begun)[kI2cBusCount], const I2cTransfer& transfer) {
  if (bus >= kI2cBusCount || !begun[bus]) return Status::kNotStarted;
  if (transfer.address > 0x7F || transfer.write_length > kI2cMaxTransferBytes ||
      transfer.read_length > kI2cMaxTransferBytes) {
    return Status::kBadArgument;
  }
  return Status::kOk;
}

/// i2c_poll() of a backend whose transfers end inside i2c_start(): hands over the bus's result
/// once, then kIdle. Context: loop.
inline I2cResult i2c_take_result(uint8_t bus, I2cResult (&latest)[kI2cBusCount]) {
  if (bus >= kI2cBusCount) return I2cResult::kIdle;
  const I2cResult result = latest[bus];
  latest[bus] = I2cResult::kIdle;
  return result;
}

}  // namespace stepdance::hal
