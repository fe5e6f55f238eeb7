// I2cBusModel: address decoding and bit-time accounting.
#include "models/i2c_bus.hpp"

#include <cstring>

namespace stepdance::sim {
namespace {

constexpr uint64_t kBitsPerByte = 9;  // 8 data bits and the acknowledge

SimTime bits_to_ns(uint64_t bits, uint32_t clock_hz) {
  return static_cast<SimTime>((bits * 1000000000ull + clock_hz / 2) / clock_hz);
}

}  // namespace

uint64_t I2cBusModel::transfer_bits(size_t write_length, size_t read_length) {
  const bool writes = write_length > 0 || read_length == 0;  // an empty transfer still sends its address
  uint64_t bits = 2;                                         // START and STOP
  if (writes) bits += kBitsPerByte * (1 + write_length);
  if (read_length > 0) bits += kBitsPerByte * (1 + read_length) + (writes ? 1 : 0);  // repeated START
  return bits;
}

I2cOutcome I2cBusModel::transfer(SimTime time, uint32_t clock_hz, uint8_t address, const uint8_t* write,
                                 size_t write_length, uint8_t* read, size_t read_length, SimTime* wire_ns) {
  if (read != nullptr && read_length > 0) std::memset(read, 0xFF, read_length);  // an idle line reads high
  if (fault_ == I2cBusFault::kLineHeldLow) {
    *wire_ns = bits_to_ns(1, clock_hz);  // the START cannot complete: the controller flags it at once
    return I2cOutcome::kBusError;
  }
  const auto found = devices_.find(address);
  if (found == devices_.end()) {
    *wire_ns = bits_to_ns(2 + kBitsPerByte, clock_hz);  // START, address, NACK, STOP
    return I2cOutcome::kAddressNack;
  }
  *wire_ns = bits_to_ns(transfer_bits(write_length, read_length), clock_hz);
  if (write_length > 0 && !found->second->write(time, write, write_length)) return I2cOutcome::kDataNack;
  if (read_length > 0) found->second->read(time, read, read_length);
  return I2cOutcome::kOk;
}

}  // namespace stepdance::sim
