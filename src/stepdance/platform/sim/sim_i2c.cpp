// The simulator backend of hal/i2c.hpp: each transfer is answered at once by the host's device
// models, then the loop waits for the transfer's time on the wire (delay_ns), as it does on a
// Teensy whose Wire library blocks until the transfer ends. Frames keep running meanwhile.
#if defined(STEPDANCE_PLATFORM_SIM)

#include "board/abi/board_abi.h"
#include "stepdance/hal/i2c.hpp"
#include "stepdance/platform/sim/host_link.hpp"

namespace stepdance::hal {
namespace {

constexpr uint32_t kSlowestClockHz = 100000;
constexpr uint32_t kFastestClockHz = 1000000;

bool begun[kI2cBusCount] = {};
I2cResult latest[kI2cBusCount] = {};

}  // namespace

Status i2c_begin(uint8_t bus, uint32_t clock_hz) {
  if (bus >= kI2cBusCount) return Status::kNoSuchPin;
  if (clock_hz < kSlowestClockHz || clock_hz > kFastestClockHz) return Status::kBadArgument;
  const auto claimed = static_cast<Status>(sim_runtime::host().i2c_begin(sim_runtime::host_context(), bus, clock_hz));
  if (claimed == Status::kOk) begun[bus] = true;
  return claimed;
}

// Answered at once by the host's device model; simulated time then advances by the transfer's wire
// time, running the frames that fall in it, as a blocking Wire transfer would on a Teensy.
Status i2c_start(uint8_t bus, const I2cTransfer& transfer) {
  const Status valid = i2c_check_start(bus, begun, transfer);
  if (valid != Status::kOk) return valid;
  int64_t wire_ns = 0;
  const int result =
      sim_runtime::host().i2c_transfer(sim_runtime::host_context(), bus, transfer.address, transfer.write,
                                       transfer.write_length, transfer.read, transfer.read_length, &wire_ns);
  latest[bus] = static_cast<I2cResult>(result);
  if (wire_ns > 0) sim_runtime::set_now_ns(sim_runtime::host().delay_ns(sim_runtime::host_context(), wire_ns));
  return Status::kOk;
}

I2cResult i2c_poll(uint8_t bus) { return i2c_take_result(bus, latest); }

}  // namespace stepdance::hal

#endif  // STEPDANCE_PLATFORM_SIM
