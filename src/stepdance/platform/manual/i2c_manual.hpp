// Test controls of the manual backend's I2C: a scripted bus that records every transfer.
#pragma once

#include <stdint.h>

#include <functional>
#include <vector>

#include "stepdance/hal/i2c.hpp"

namespace stepdance::hal_manual {

/// One transfer as the bus saw it.
struct I2cRecord {
  uint8_t bus = 0;
  uint8_t address = 0;
  std::vector<uint8_t> written;
  uint16_t read_length = 0;
};

/// Answers a transfer: fills `read` (read_length bytes, preset to 0xFF) and returns its result.
using I2cResponder = std::function<hal::I2cResult(const I2cRecord& transfer, uint8_t* read, uint16_t read_length)>;

/// Forgets buses, transfers and the responder (every transfer is then acknowledged).
void i2c_reset();
/// Who answers transfers from now on.
void i2c_set_responder(I2cResponder responder);
/// Transfers stay kPending until i2c_release() when true (an interrupt-driven backend's view).
void i2c_hold(bool hold);
/// Ends the held transfer on `bus` (its result comes from the responder).
void i2c_release(uint8_t bus);
/// Every transfer started since i2c_reset(), in order.
const std::vector<I2cRecord>& i2c_log();
/// The clock a bus was begun with (0 if not begun).
uint32_t i2c_clock(uint8_t bus);

}  // namespace stepdance::hal_manual
