// The manual backend of hal/i2c.hpp: transfers are recorded and answered by a test's responder.
#if defined(STEPDANCE_PLATFORM_MANUAL)

#include "i2c_manual.hpp"

#include <cstring>

namespace stepdance::hal_manual {
namespace {

struct ManualI2c {
  uint32_t clock_hz[hal::kI2cBusCount] = {};
  hal::I2cResult latest[hal::kI2cBusCount] = {};
  bool holding = false;
  hal::I2cTransfer held[hal::kI2cBusCount] = {};
  std::vector<I2cRecord> log;
  I2cResponder responder;
};

ManualI2c& state() {
  static ManualI2c instance;
  return instance;
}

// Records every transfer, then lets the test's responder answer. The read buffer is first filled with
// 0xFF, what an idle I2C bus reads (the lines are pulled high), so a device that does not answer
// gives the same bytes as on hardware.
hal::I2cResult answer(uint8_t bus, const hal::I2cTransfer& transfer) {
  I2cRecord record;
  record.bus = bus;
  record.address = transfer.address;
  record.written.assign(transfer.write, transfer.write + transfer.write_length);
  record.read_length = transfer.read_length;
  state().log.push_back(record);
  if (transfer.read_length > 0) std::memset(transfer.read, 0xFF, transfer.read_length);
  if (!state().responder) return hal::I2cResult::kOk;
  return state().responder(record, transfer.read, transfer.read_length);
}

}  // namespace

void i2c_reset() { state() = ManualI2c{}; }
void i2c_set_responder(I2cResponder responder) { state().responder = std::move(responder); }
// Holding keeps transfers kPending until i2c_release(), so a test can check that the drivers poll
// instead of blocking on the bus.
void i2c_hold(bool hold) { state().holding = hold; }
void i2c_release(uint8_t bus) {
  if (bus < hal::kI2cBusCount && state().latest[bus] == hal::I2cResult::kPending) {
    state().latest[bus] = answer(bus, state().held[bus]);
  }
}
const std::vector<I2cRecord>& i2c_log() { return state().log; }
uint32_t i2c_clock(uint8_t bus) { return bus < hal::kI2cBusCount ? state().clock_hz[bus] : 0; }

}  // namespace stepdance::hal_manual

namespace stepdance::hal {

// Accepts the I2C standard-mode to fast-mode-plus range (100 kHz … 1 MHz), as the Teensy backend does.
Status i2c_begin(uint8_t bus, uint32_t clock_hz) {
  if (bus >= kI2cBusCount) return Status::kNoSuchPin;
  if (clock_hz < 100000 || clock_hz > 1000000) return Status::kBadArgument;
  hal_manual::state().clock_hz[bus] = clock_hz;
  return Status::kOk;
}

// One transfer in flight per bus, as on the hardware's single I2C controller; addresses are 7-bit.
Status i2c_start(uint8_t bus, const I2cTransfer& transfer) {
  auto& bus_state = hal_manual::state();
  if (bus >= kI2cBusCount || bus_state.clock_hz[bus] == 0) return Status::kNotStarted;
  if (bus_state.latest[bus] == I2cResult::kPending) return Status::kBusy;
  if (transfer.address > 0x7F || transfer.write_length > kI2cMaxTransferBytes ||
      transfer.read_length > kI2cMaxTransferBytes) {
    return Status::kBadArgument;
  }
  if (bus_state.holding) {
    bus_state.held[bus] = transfer;
    bus_state.latest[bus] = I2cResult::kPending;
  } else {
    bus_state.latest[bus] = hal_manual::answer(bus, transfer);
  }
  return Status::kOk;
}

// A finished result is reported once and then the bus reads idle, so a caller cannot take one answer
// twice.
I2cResult i2c_poll(uint8_t bus) {
  if (bus >= kI2cBusCount) return I2cResult::kIdle;
  I2cResult& latest = hal_manual::state().latest[bus];
  const I2cResult result = latest;
  if (result != I2cResult::kPending) latest = I2cResult::kIdle;
  return result;
}

}  // namespace stepdance::hal

#endif  // STEPDANCE_PLATFORM_MANUAL
