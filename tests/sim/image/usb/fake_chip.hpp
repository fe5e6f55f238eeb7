// A fake chip around the USB models: a scheduler, 64 KB of RAM at 0x20000000 and a recorded
// interrupt line; and a fake world that feeds and collects the serial bytes.
#pragma once

#include <cstdint>
#include <cstring>
#include <deque>
#include <vector>

#include "image/chip/board_io.hpp"
#include "image/chip/chip_context.hpp"
#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim::image::usb::testing {

class FakeChip : public ChipContext {
 public:
  static constexpr uint32_t kRamBase = 0x20000000u;
  static constexpr uint32_t kRamBytes = 0x10000u;

  SimTime now_ns() const override { return scheduler_.now(); }
  uint64_t cycles() const override { return static_cast<uint64_t>(scheduler_.now()) * 6 / 10; }
  uint32_t core_clock_hz() const override { return 600000000u; }
  Scheduler& scheduler() override { return scheduler_; }
  void set_irq_level(unsigned irq, bool high) override {
    levels.push_back({irq, high, scheduler_.now()});
    if (irq == 113) irq113 = high;
  }
  void stop_cpu_run() override { ++stops; }
  bool read_memory(uint32_t address, void* data, size_t bytes) override {
    if (!inside(address, bytes)) return false;
    std::memcpy(data, ram.data() + (address - kRamBase), bytes);
    return true;
  }
  bool write_memory(uint32_t address, const void* data, size_t bytes) override {
    if (!inside(address, bytes)) return false;
    std::memcpy(ram.data() + (address - kRamBase), data, bytes);
    return true;
  }

  uint32_t word(uint32_t address) const {
    uint32_t value = 0;
    std::memcpy(&value, ram.data() + (address - kRamBase), 4);
    return value;
  }
  void set_word(uint32_t address, uint32_t value) { std::memcpy(ram.data() + (address - kRamBase), &value, 4); }

  struct Level {
    unsigned irq;
    bool high;
    SimTime time;
  };
  std::vector<Level> levels;
  bool irq113 = false;
  int stops = 0;
  std::vector<uint8_t> ram = std::vector<uint8_t>(kRamBytes, 0);

 private:
  static bool inside(uint32_t address, size_t bytes) {
    return address >= kRamBase && uint64_t{address} + bytes <= uint64_t{kRamBase} + kRamBytes;
  }
  Scheduler scheduler_;
};

/// The world side: serial bytes only (the USB host touches nothing else).
class FakeWorld : public BoardIo {
 public:
  void pin_config(SimTime, uint8_t, PinConfig) override {}
  void pin_drive(SimTime, uint8_t, bool) override {}
  bool pin_level(SimTime, uint8_t) override { return false; }
  void port_frame(uint8_t, SimTime, const protocol::FrameWords&, SimTime) override {}
  int64_t encoder_counts(SimTime, uint8_t) override { return 0; }
  uint16_t analog_level(SimTime, uint8_t) override { return 0; }
  int i2c_transfer(SimTime, uint8_t, uint32_t, uint8_t, const uint8_t*, size_t, uint8_t*, size_t, SimTime&) override {
    return 3;
  }
  size_t serial_from_device(SimTime now_ns, const uint8_t* data, size_t length) override {
    const size_t taken = length < accept_limit ? length : accept_limit;
    received.insert(received.end(), data, data + taken);
    if (taken > 0) received_at.push_back(now_ns);
    return taken;
  }
  size_t serial_to_device(SimTime, uint8_t* data, size_t capacity) override {
    size_t n = 0;
    while (n < capacity && !to_device.empty()) {
      data[n++] = to_device.front();
      to_device.pop_front();
    }
    return n;
  }

  std::deque<uint8_t> to_device;
  std::vector<uint8_t> received;
  std::vector<SimTime> received_at;
  size_t accept_limit = static_cast<size_t>(-1);
};

}  // namespace stepdance::sim::image::usb::testing
