// A board's two QWIIC buses: the devices plugged into each, its clock, and the time the sketch's
// loop spends in transfers.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "common/sim_time.hpp"
#include "models/i2c_bus.hpp"

namespace stepdance::sim {

/// Time the sketch's loop spent in I2C transfers (their wire time at the bus clock): the most in
/// any one loop pass, and in all. Transfers in setup() are counted apart.
struct I2cTiming {
  SimTime max_loop_pass_ns = 0;
  SimTime total_ns = 0;
  SimTime setup_ns = 0;
  uint64_t transfers = 0;
  uint64_t loop_passes_with_i2c = 0;
};

/// The QWIIC buses 0 and 1 of one board. Context: host, on the simulation's thread.
class BoardI2c {
 public:
  static constexpr uint8_t kBuses = 2;

  // ---- wiring ----
  /// Plugs `device` into bus `bus` at 7-bit `address` (not owned).
  void attach(uint8_t bus, uint8_t address, I2cDevice* device) { buses_[bus].model.attach(address, device); }
  /// Breaks or mends bus `bus` (fault scenarios and tests).
  void set_fault(uint8_t bus, I2cBusFault fault) { buses_[bus].model.set_fault(fault); }

  // ---- the program side ----
  /// Sets the clock of bus `bus` in Hz (0 = not begun); false for a bus the board lacks.
  bool begin(uint8_t bus, uint32_t clock_hz);
  /// One transfer at `now_ns`: an I2cOutcome as int, its wire time in `wire_ns`. A bus not begun
  /// answers kBusError.
  int transfer(uint8_t bus, uint8_t address, const uint8_t* write, size_t write_length, uint8_t* read,
               size_t read_length, SimTime now_ns, int64_t* wire_ns);
  /// The loop pass starts / ends: transfers in between count towards its time, others to setup.
  void begin_loop_pass();
  void end_loop_pass();
  /// Adds the pass that just ended to the timing, if it made transfers (a pass that stopped the
  /// sketch is not counted).
  void count_loop_pass();

  const I2cTiming& timing() const { return timing_; }

 private:
  struct Bus {
    I2cBusModel model;
    uint32_t clock_hz = 0;  ///< 0 until the sketch begins the bus
  };
  std::array<Bus, kBuses> buses_{};
  I2cTiming timing_;
  bool in_loop_pass_ = false;
  SimTime ns_this_pass_ = 0;
};

}  // namespace stepdance::sim
