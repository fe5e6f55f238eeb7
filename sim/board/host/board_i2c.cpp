// BoardI2c: transfers on the bus models, and their time per loop pass.
#include "board/host/board_i2c.hpp"

#include <algorithm>

namespace stepdance::sim {

bool BoardI2c::begin(uint8_t bus, uint32_t clock_hz) {
  if (bus >= buses_.size()) return false;
  buses_[bus].clock_hz = clock_hz;
  return true;
}

int BoardI2c::transfer(uint8_t bus, uint8_t address, const uint8_t* write, size_t write_length, uint8_t* read,
                       size_t read_length, SimTime now_ns, int64_t* wire_ns) {
  *wire_ns = 0;
  if (bus >= buses_.size() || buses_[bus].clock_hz == 0) return static_cast<int>(I2cOutcome::kBusError);
  SimTime duration = 0;
  const I2cOutcome outcome = buses_[bus].model.transfer(now_ns, buses_[bus].clock_hz, address, write, write_length,
                                                        read, read_length, &duration);
  *wire_ns = duration;
  ++timing_.transfers;
  timing_.total_ns += duration;
  if (in_loop_pass_) {
    ns_this_pass_ += duration;
  } else {
    timing_.setup_ns += duration;
  }
  return static_cast<int>(outcome);
}

void BoardI2c::begin_loop_pass() {
  in_loop_pass_ = true;
  ns_this_pass_ = 0;
}

void BoardI2c::end_loop_pass() { in_loop_pass_ = false; }

void BoardI2c::count_loop_pass() {
  if (ns_this_pass_ == 0) return;
  ++timing_.loop_passes_with_i2c;
  timing_.max_loop_pass_ns = std::max(timing_.max_loop_pass_ns, ns_this_pass_);
}

}  // namespace stepdance::sim
