// hal/i2c.hpp on the Teensy 4.x through Teensyduino's Wire (QWIIC0) and Wire1 (QWIIC1).
//
// Wire transfers block until their last byte is on the wire, so i2c_start() runs the whole
// transfer and i2c_poll() hands its result over: the loop pass that starts a transfer spends its
// wire time (≤ 0.9 ms for kI2cMaxTransferBytes at 400 kHz), the frame and kilohertz interrupts
// preempt it as usual. A bus that hangs is bounded by Wire's own timeouts and reported.
#if defined(__IMXRT1062__)

#include "stepdance/hal/i2c.hpp"
#include "stepdance/platform/teensy/teensyduino_services.hpp"

namespace stepdance::hal {
namespace {

bool begun[kI2cBusCount] = {};
I2cResult latest[kI2cBusCount] = {};

// Wire's endTransmission codes.
I2cResult from_wire_code(uint8_t code) {
  switch (code) {
    case 0: return I2cResult::kOk;
    case 2: return I2cResult::kAddressNack;
    case 3: return I2cResult::kDataNack;
    case 5: return I2cResult::kTimeout;
    default: return I2cResult::kBusError;  // 1 (too long: never asked), 4 (other)
  }
}

I2cResult run(uint8_t bus, const I2cTransfer& transfer) {
  const bool reads = transfer.read_length > 0;
  if (transfer.write_length > 0 || !reads) {
    const I2cResult written = from_wire_code(
        platform::teensy::services::wire_write(bus, transfer.address, transfer.write, transfer.write_length, !reads));
    if (written != I2cResult::kOk || !reads) return written;
  }
  const size_t received =
      platform::teensy::services::wire_read(bus, transfer.address, transfer.read, transfer.read_length);
  if (received == transfer.read_length) return I2cResult::kOk;
  // Nothing at all after no write: nobody answered the address.
  return received == 0 && transfer.write_length == 0 ? I2cResult::kAddressNack : I2cResult::kBusError;
}

}  // namespace

Status i2c_begin(uint8_t bus, uint32_t clock_hz) {
  if (bus >= kI2cBusCount) return Status::kNoSuchPin;
  if (clock_hz < 100000 || clock_hz > 1000000) return Status::kBadArgument;
  platform::teensy::services::wire_begin(bus, clock_hz);
  begun[bus] = true;
  return Status::kOk;
}

Status i2c_start(uint8_t bus, const I2cTransfer& transfer) {
  const Status valid = i2c_check_start(bus, begun, transfer);
  if (valid != Status::kOk) return valid;
  latest[bus] = run(bus, transfer);
  return Status::kOk;
}

I2cResult i2c_poll(uint8_t bus) { return i2c_take_result(bus, latest); }

}  // namespace stepdance::hal

#endif  // __IMXRT1062__
