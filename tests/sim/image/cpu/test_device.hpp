// A peripheral for the CPU tests at 0x40100000: fixtures mark moments (the device logs the value
// with the core cycle of the store) and lower or raise interrupt lines.
#pragma once

#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "image/chip/chip_context.hpp"
#include "image/chip/peripheral.hpp"

namespace stepdance::sim::image::testing {

class TestDevice : public Peripheral {
 public:
  struct Mark {
    uint32_t value;
    uint64_t cycle;
    bool operator==(const Mark& other) const { return value == other.value && cycle == other.cycle; }
  };

  explicit TestDevice(ChipContext& chip) : chip_(chip) {}
  const char* name() const override { return "TESTDEV"; }
  uint32_t base() const override { return 0x40100000; }
  uint32_t size_bytes() const override { return 0x100; }
  /// 0x0C reads 0x5A; 0x14 answers with a bus error; everything else unmodelled.
  Access read(uint32_t offset, uint8_t, uint32_t& value) override {
    if (offset == 0x14) return Access::kBusError;
    if (offset != 0x0C) return Access::kUnmodelled;
    value = 0x5A;
    return Access::kOk;
  }
  /// 0x00: lower IRQ line `value`; 0x04: log a mark; 0x08: raise IRQ line `value`; 0x10: end the
  /// CPU's run (if stop_on_write).
  Access write(uint32_t offset, uint8_t, uint32_t value) override {
    switch (offset) {
      case 0x10:
        if (stop_on_write) chip_.stop_cpu_run();
        return Access::kOk;
      case 0x00: chip_.set_irq_level(value, false); return Access::kOk;
      case 0x04: marks.push_back({value, chip_.cycles()}); return Access::kOk;
      case 0x08: chip_.set_irq_level(value, true); return Access::kOk;
      default: return Access::kUnmodelled;
    }
  }
  /// The cycle of the first mark with `value` (fails the test if none).
  uint64_t cycle_of(uint32_t value) const {
    for (const Mark& mark : marks) {
      if (mark.value == value) return mark.cycle;
    }
    ADD_FAILURE() << "no mark " << value;
    return 0;
  }

  /// The cycles of every mark with `value`, in order.
  std::vector<uint64_t> cycles_of(uint32_t value) const {
    std::vector<uint64_t> cycles;
    for (const Mark& mark : marks) {
      if (mark.value == value) cycles.push_back(mark.cycle);
    }
    return cycles;
  }
  /// The mark values in order.
  std::vector<uint32_t> values() const {
    std::vector<uint32_t> list;
    for (const Mark& mark : marks) list.push_back(mark.value);
    return list;
  }

  std::vector<Mark> marks;
  bool stop_on_write = false;

 private:
  ChipContext& chip_;
};

}  // namespace stepdance::sim::image::testing
