// A fake chip around the RT1062 models under test: a real scheduler, a settable clock, recorded
// interrupt levels, and a fake world (BoardIo) that records pin traffic and plays levels.
#pragma once

#include <map>
#include <vector>

#include "image/chip/board_io.hpp"
#include "image/chip/chip_context.hpp"
#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim::image::rt1062::testing {

class FakeChip : public ChipContext {
 public:
  SimTime now_ns() const override { return scheduler_.now(); }
  uint64_t cycles() const override { return 0; }
  uint32_t core_clock_hz() const override { return 600000000u; }
  Scheduler& scheduler() override { return scheduler_; }
  void set_irq_level(unsigned irq, bool high) override {
    irq_levels[irq] = high;
    irq_log.push_back({scheduler_.now(), irq, high});
  }
  void stop_cpu_run() override { ++stops; }
  bool read_memory(uint32_t, void*, size_t) override { return false; }
  bool write_memory(uint32_t, const void*, size_t) override { return false; }

  /// Moves simulated time to `time_ns`, running the events due on the way.
  void advance_to(SimTime time_ns) { scheduler_.run_until(time_ns); }

  struct IrqChange {
    SimTime time;
    unsigned irq;
    bool high;
  };
  std::map<unsigned, bool> irq_levels;
  std::vector<IrqChange> irq_log;
  int stops = 0;

 private:
  Scheduler scheduler_;
};

class FakeWorld : public BoardIo {
 public:
  void pin_config(SimTime now, uint8_t pin, PinConfig config) override { configs.push_back({now, pin, config}); }
  void pin_drive(SimTime now, uint8_t pin, bool high) override { drives.push_back({now, pin, high}); }
  bool pin_level(SimTime, uint8_t pin) override { return levels[pin]; }
  void port_frame(uint8_t, SimTime, const protocol::FrameWords&, SimTime) override {}
  int64_t encoder_counts(SimTime, uint8_t) override { return 0; }
  uint16_t analog_level(SimTime now, uint8_t pin) override {
    analog_reads.push_back({now, pin});
    return analog[pin];
  }
  int i2c_transfer(SimTime, uint8_t, uint32_t, uint8_t, const uint8_t*, size_t, uint8_t*, size_t, SimTime&) override {
    return 0;
  }
  size_t serial_from_device(SimTime, const uint8_t*, size_t) override { return 0; }
  size_t serial_to_device(SimTime, uint8_t*, size_t) override { return 0; }

  struct Config {
    SimTime time;
    uint8_t pin;
    PinConfig config;
  };
  struct Drive {
    SimTime time;
    uint8_t pin;
    bool high;
  };
  struct AnalogRead {
    SimTime time;
    uint8_t pin;
  };
  std::vector<Config> configs;
  std::vector<Drive> drives;
  std::vector<AnalogRead> analog_reads;
  std::map<uint8_t, bool> levels;
  std::map<uint8_t, uint16_t> analog;
};

}  // namespace stepdance::sim::image::rt1062::testing
