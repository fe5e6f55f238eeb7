// A fake chip and world for driving the RT1062 motion blocks from tests: a scheduler for time,
// a recorded interrupt line, a recorded BoardIo, and CCM clock registers on the bus.
#pragma once

#include <cstdint>
#include <cstring>
#include <map>
#include <vector>

#include "image/chip/board_io.hpp"
#include "image/chip/chip_context.hpp"
#include "image/chip/peripheral.hpp"
#include "image/chip/peripheral_bus.hpp"
#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim::image::testing {

/// One interrupt line change.
struct IrqChange {
  SimTime at_ns;
  unsigned irq;
  bool high;
};

/// Time is the scheduler's; the core runs at 600 MHz (Teensyduino's default).
class FakeChip : public ChipContext {
 public:
  SimTime now_ns() const override { return scheduler_.now(); }
  uint64_t cycles() const override { return static_cast<uint64_t>(scheduler_.now()) * 3 / 5; }
  uint32_t core_clock_hz() const override { return 600000000u; }
  Scheduler& scheduler() override { return scheduler_; }
  void set_irq_level(unsigned irq, bool high) override {
    changes.push_back({scheduler_.now(), irq, high});
    levels[irq] = high;
  }
  void stop_cpu_run() override { ++stops; }
  bool read_memory(uint32_t, void*, size_t) override { return false; }
  bool write_memory(uint32_t, const void*, size_t) override { return false; }

  /// Rising edges of `irq`, in order.
  std::vector<SimTime> rises(unsigned irq) const {
    std::vector<SimTime> times;
    for (const IrqChange& change : changes) {
      if (change.irq == irq && change.high) times.push_back(change.at_ns);
    }
    return times;
  }
  bool level(unsigned irq) const {
    const auto found = levels.find(irq);
    return found != levels.end() && found->second;
  }

  std::vector<IrqChange> changes;
  std::map<unsigned, bool> levels;
  int stops = 0;

 private:
  mutable Scheduler scheduler_;
};

/// One port_frame call.
struct PortFrame {
  uint8_t port;
  SimTime start_ns;
  protocol::FrameWords words;
  SimTime frame_ns;
};

/// One i2c_transfer call, and the device's answer.
struct I2cCall {
  SimTime at_ns;
  uint8_t bus;
  uint32_t clock_hz;
  uint8_t address;
  std::vector<uint8_t> written;
  size_t read_length;
};

/// Records what the chip does to the world; pins, encoders and I2C devices are set by the test.
class FakeIo : public BoardIo {
 public:
  void pin_config(SimTime, uint8_t, PinConfig) override {}
  void pin_drive(SimTime, uint8_t pin, bool high) override { pins[pin] = high; }
  bool pin_level(SimTime, uint8_t pin) override { return pins[pin]; }
  void port_frame(uint8_t port, SimTime start_ns, const protocol::FrameWords& words, SimTime frame_ns) override {
    frames.push_back({port, start_ns, words, frame_ns});
  }
  int64_t encoder_counts(SimTime, uint8_t index) override { return encoders[index]; }
  uint16_t analog_level(SimTime, uint8_t) override { return 0; }
  int i2c_transfer(SimTime now_ns, uint8_t bus, uint32_t clock_hz, uint8_t address, const uint8_t* write,
                   size_t write_length, uint8_t* read, size_t read_length, SimTime& wire_ns) override {
    i2c_calls.push_back(
        {now_ns, bus, clock_hz, address, std::vector<uint8_t>(write, write + write_length), read_length});
    // 9 bit times per byte plus start/stop, as a real bus at clock_hz would take.
    wire_ns = static_cast<SimTime>((9 * (1 + write_length + (read_length ? 1 + read_length : 0)) + 2) * 1000000000LL /
                                   clock_hz);
    const auto forced = i2c_results.find(address);
    if (forced != i2c_results.end()) return forced->second;
    const auto device = i2c_devices.find(address);
    if (device == i2c_devices.end()) return 3;  // hal::I2cResult::kAddressNack
    for (size_t i = 0; i < read_length; ++i) read[i] = device->second[i % device->second.size()];
    return 2;  // hal::I2cResult::kOk
  }
  size_t serial_from_device(SimTime, const uint8_t*, size_t length) override { return length; }
  size_t serial_to_device(SimTime, uint8_t*, size_t) override { return 0; }

  std::map<uint8_t, bool> pins;
  std::map<uint8_t, int64_t> encoders;
  std::map<uint8_t, std::vector<uint8_t>> i2c_devices;  ///< address → bytes it answers reads with
  std::map<uint8_t, int> i2c_results;                   ///< address → a result to force (4 = data NACK)
  std::vector<PortFrame> frames;
  std::vector<I2cCall> i2c_calls;
};

/// A stand-in for the CCM and CCM_ANALOG blocks: plain storage with the reference manual's
/// reset values of the registers the clock roots are read from (RM §14.7, §14.8).
class FakeClockBlock : public Peripheral {
 public:
  FakeClockBlock(const char* name, uint32_t base) : name_(name), base_(base) {}
  const char* name() const override { return name_; }
  uint32_t base() const override { return base_; }
  uint32_t size_bytes() const override { return 0x1000; }
  Access read(uint32_t offset, uint8_t, uint32_t& value) override {
    value = registers[offset];
    return Access::kOk;
  }
  Access write(uint32_t offset, uint8_t, uint32_t value) override {
    registers[offset] = value;
    return Access::kOk;
  }
  std::map<uint32_t, uint32_t> registers;

 private:
  const char* name_;
  uint32_t base_;
};

/// The PIT as plain storage, except that TFLGn (0x10C + 0x10 n) is write-1-to-clear as on the
/// chip (RM §53.4): no channel ever expires by itself; a test makes an expiry by setting TFLG
/// through `registers` and pulsing the XBAR input itself.
class FakePit : public FakeClockBlock {
 public:
  FakePit() : FakeClockBlock("PIT", 0x40084000u) {}
  Access write(uint32_t offset, uint8_t bytes, uint32_t value) override {
    writes.emplace_back(offset, value);
    if (offset >= 0x100 && (offset & 0xFu) == 0xC) {
      registers[offset] &= ~value;
      return Access::kOk;
    }
    return FakeClockBlock::write(offset, bytes, value);
  }
  std::vector<std::pair<uint32_t, uint32_t>> writes;  ///< (offset, value), in order
};

/// The fake chip, world and clock registers on one bus, clocked as Teensyduino leaves them:
/// PLL3 locked at 480 MHz, IPG = 600 MHz / 4, and the FlexIO2/3 root as the backend's
/// power_up() sets it (PLL3 / 2 / 2 = 120 MHz) unless a test changes CS1CDR.
struct Rig {
  Rig() {
    ccm.registers[0x14] = 0x000A8300u;             // CBCDR: IPG_PODF (9:8) = 3 → ÷4
    ccm.registers[0x20] = 0x13192F06u;             // CSCMR2 reset: FLEXIO2_CLK_SEL (20:19) = 3, PLL3
    ccm.registers[0x28] = (1u << 25) | (1u << 9);  // CS1CDR: PODF 1, PRED 1 (÷2 ÷2)
    analog.registers[0x10] = 0x80003040u;          // PLL_USB1: LOCK, POWER, EN_USB_CLKS, DIV_SELECT 0 (×20)
    bus.add(ccm);
    bus.add(analog);
  }
  /// Writes through the bus as the CPU would; false if the access was refused.
  bool write(uint32_t address, uint32_t value, uint8_t bytes = 4) {
    BusRefusal refusal;
    return bus.write(address, bytes, value, refusal);
  }
  /// Reads through the bus; false if the access was refused.
  bool read(uint32_t address, uint32_t& value, uint8_t bytes = 4) {
    BusRefusal refusal;
    return bus.read(address, bytes, value, refusal);
  }
  /// A 32-bit read the test expects to succeed (0xDEADBEEF if it was refused).
  uint32_t read32(uint32_t address) {
    uint32_t value = 0;
    return read(address, value) ? value : 0xDEADBEEFu;
  }
  /// Runs the world's events up to `t_ns`.
  void run_until(SimTime t_ns) { chip.scheduler().run_until(t_ns); }

  FakeChip chip;
  FakeIo io;
  FakeClockBlock ccm{"CCM", 0x400FC000u};
  FakeClockBlock analog{"CCM_ANALOG", 0x400D8000u};
  PeripheralBus bus;
};

}  // namespace stepdance::sim::image::testing
