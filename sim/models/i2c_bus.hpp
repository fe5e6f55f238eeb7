// A simulated I2C bus: devices attached by 7-bit address, transfers timed bit by bit.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>

#include "common/sim_time.hpp"

namespace stepdance::sim {

/// A device on the bus. Both calls get the time the transfer starts.
class I2cDevice {
 public:
  virtual ~I2cDevice() = default;
  /// The master wrote `length` bytes in one transfer (after the address). False: the device
  /// refused a byte (a data NACK).
  virtual bool write(SimTime time, const uint8_t* data, size_t length) = 0;
  /// The master reads `length` bytes (after a write in the same transfer, if any).
  virtual void read(SimTime time, uint8_t* data, size_t length) = 0;
};

/// Outcomes, numbered as stepdance::hal::I2cResult.
enum class I2cOutcome : int { kOk = 2, kAddressNack = 3, kDataNack = 4, kBusError = 5, kTimeout = 6 };

/// What is wrong with the bus, for fault scenarios.
enum class I2cBusFault { kNone, kLineHeldLow };

/// One bus. Wire time of a transfer, in bit times of the clock: a START, 9 bits (8 + ACK) for
/// the address and for every byte, a repeated START and another address before a read that
/// follows a write, and a STOP. A missing device ends the transfer after its address.
class I2cBusModel {
 public:
  void attach(uint8_t address, I2cDevice* device) { devices_[address] = device; }
  bool has_device(uint8_t address) const { return devices_.count(address) != 0; }
  void set_fault(I2cBusFault fault) { fault_ = fault; }

  /// Runs one transfer at `time` with the bus clock `clock_hz`; *wire_ns receives its duration.
  I2cOutcome transfer(SimTime time, uint32_t clock_hz, uint8_t address, const uint8_t* write, size_t write_length,
                      uint8_t* read, size_t read_length, SimTime* wire_ns);

  /// Bit times of a completed transfer (see the class comment).
  static uint64_t transfer_bits(size_t write_length, size_t read_length);

 private:
  std::map<uint8_t, I2cDevice*> devices_;
  I2cBusFault fault_ = I2cBusFault::kNone;
};

}  // namespace stepdance::sim
