// LPI2C1/LPI2C3 driven as Teensyduino 1.59's Wire drives them (begin/setClock, endTransmission,
// requestFrom: the register protocol of WireIMXRT.cpp, written here from its register use).
// Expected values: RM §47.4 register layouts and reset values, the SCL formula of MCCR0, the I2C
// protocol (an absent address is NACKed, 9 bit times per byte), the fake devices' bytes.
#include "image/rt1062/lpi2c.hpp"

#include <gtest/gtest.h>

#include "motion_fakes.hpp"

namespace stepdance::sim::image {
namespace {

using testing::Rig;

constexpr uint32_t kLpi2c1 = 0x403F0000u, kLpi2c3 = 0x403F8000u;  // RM §2.3
constexpr uint32_t kMcr = 0x10, kMsr = 0x14, kMier = 0x18, kMcfgr0 = 0x20, kMcfgr1 = 0x24, kMcfgr2 = 0x28;
constexpr uint32_t kMcfgr3 = 0x2C, kMccr0 = 0x48, kMccr1 = 0x50, kMfcr = 0x58, kMfsr = 0x5C, kMtdr = 0x60;
constexpr uint32_t kMrdr = 0x70;
constexpr uint32_t kSdf = 1u << 9, kNdf = 1u << 10, kBbf = 1u << 25, kMbf = 1u << 24;
constexpr uint32_t kCmdTransmit = 0u << 8, kCmdReceive = 1u << 8, kCmdStop = 2u << 8, kCmdStart = 4u << 8;

/// Wire's master protocol on one LPI2C, polling with 1 µs of CPU time between accesses.
struct WireLike {
  Rig& rig;
  uint32_t base;

  uint32_t reg(uint32_t offset) {
    rig.run_until(rig.chip.now_ns() + 1000);
    return rig.read32(base + offset);
  }
  void set(uint32_t offset, uint32_t value) {
    rig.run_until(rig.chip.now_ns() + 1000);
    ASSERT_TRUE(rig.write(base + offset, value)) << std::hex << offset;
  }
  // begin(): reset, then setClock(frequency) with Wire's constants for < 400 kHz and < 1 MHz.
  void begin(uint32_t frequency) {
    set(kMcr, 1u << 1);  // RST
    set(kMcr, 0);
    if (frequency < 400000) {
      set(kMccr0, (55u << 8) | 59u | (25u << 24) | (40u << 16));
      set(kMcfgr1, 1);
      set(kMcfgr2, (5u << 24) | (5u << 16) | 3000u);
    } else {
      set(kMccr0, (26u << 8) | 28u | (12u << 24) | (18u << 16));
      set(kMcfgr1, 0);
      set(kMcfgr2, (2u << 24) | (2u << 16) | 3600u);
    }
    set(kMcfgr3, (15000u * 24u / 256u + 1u) << 8);
    set(kMccr1, reg(kMccr0));
    set(kMcfgr0, 0);
    set(kMfcr, (1u << 16) | 1u);
    set(kMcr, 1);  // MEN
  }
  bool wait_idle() {
    for (int i = 0; i < 20000; ++i) {
      const uint32_t status = reg(kMsr);
      if (!(status & kBbf) || (status & kMbf)) {
        set(kMsr, 0x7F00);
        return true;
      }
    }
    return false;
  }
  // endTransmission: 0 ok, 2 NACK, 4 timeout.
  int end_transmission(const std::vector<uint8_t>& bytes, bool stop) {
    if (!wait_idle()) return 4;
    size_t index = 0;  // 0 = START, 1..n-1 data, n = STOP
    for (int i = 0; i < 20000; ++i) {
      if (index <= bytes.size()) {
        for (uint32_t used = reg(kMfsr) & 7u; used < 4; ++used) {
          if (index == 0)
            set(kMtdr, kCmdStart | bytes[0]);
          else if (index < bytes.size())
            set(kMtdr, kCmdTransmit | bytes[index]);
          else if (stop)
            set(kMtdr, kCmdStop);
          if (index++ >= bytes.size()) break;
        }
      }
      const uint32_t status = reg(kMsr);
      if (status & kNdf) {
        set(kMcr, reg(kMcr) | (1u << 8) | (1u << 9));
        set(kMtdr, kCmdStop);
        return 2;
      }
      if (index > bytes.size() && (reg(kMfsr) & 7u) == 0 && ((status & kSdf) || !stop)) return 0;
    }
    return 4;
  }
  // requestFrom: the bytes received.
  std::vector<uint8_t> request_from(uint8_t address, uint8_t length) {
    std::vector<uint8_t> received;
    if (!wait_idle()) return received;
    int state = 0;
    for (int i = 0; i < 20000; ++i) {
      for (uint32_t used = reg(kMfsr) & 7u; used < 4 && state < 3; ++used, ++state) {
        if (state == 0) set(kMtdr, kCmdStart | 1u | (address << 1));
        if (state == 1) set(kMtdr, kCmdReceive | (length - 1u));
        if (state == 2) set(kMtdr, kCmdStop);
      }
      for (uint32_t count = (reg(kMfsr) >> 16) & 7u; count > 0; --count) {
        received.push_back(static_cast<uint8_t>(reg(kMrdr)));
      }
      const uint32_t status = reg(kMsr);
      if (status & kNdf) {
        set(kMcr, reg(kMcr) | (1u << 8) | (1u << 9));
        set(kMtdr, kCmdStop);
        break;
      }
      if (received.size() >= length && state >= 3 && (reg(kMfsr) & 7u) == 0 && (status & kSdf)) break;
    }
    return received;
  }
};

struct Lpi2cTest : ::testing::Test {
  Lpi2cTest() {
    // Wire's begin(): LPI2C_CLK_SEL = oscillator, PODF 0 (CCM_CSCDR2, RM §14.7.13).
    rig.ccm.registers[0x38] = 1u << 18;
    rig.bus.add(lpi2c1);
    rig.bus.add(lpi2c3);
    rig.io.i2c_devices[0x3F] = {0x11, 0x22, 0x33};
  }
  Rig rig;
  Lpi2c lpi2c1{1, rig.bus, rig.chip, rig.io};
  Lpi2c lpi2c3{3, rig.bus, rig.chip, rig.io};
  WireLike wire{rig, kLpi2c1};
  WireLike wire1{rig, kLpi2c3};
};

TEST_F(Lpi2cTest, ResetValuesFollowTheManual) {
  EXPECT_EQ(rig.read32(kLpi2c1 + kMcr), 0u);
  EXPECT_EQ(rig.read32(kLpi2c1 + kMsr), 1u) << "TDF: the empty FIFO is at its watermark";
  EXPECT_EQ(rig.read32(kLpi2c1 + kMrdr), 1u << 14) << "RXEMPTY";
  EXPECT_EQ(rig.read32(kLpi2c1 + kMfsr), 0u);
}

TEST_F(Lpi2cTest, SetClockGivesTheRequestedSclFrequency) {
  wire.begin(100000);
  // (CLKHI 55 + CLKLO 59 + 2 + floor((2 + FILTSCL 5) / 2)) × 2 = 238 clocks of 24 MHz.
  EXPECT_EQ(lpi2c1.scl_hz(), 24000000u / 238u);
  wire.begin(400000);
  EXPECT_EQ(lpi2c1.scl_hz(), 400000u);  // (26 + 28 + 2 + 4) × 1 = 60 clocks
}

TEST_F(Lpi2cTest, AWriteToAnAbsentAddressIsNacked) {
  wire.begin(400000);
  EXPECT_EQ(wire.end_transmission({0x3C << 1, 0x00, 0xAF}, true), 2);
  ASSERT_EQ(rig.io.i2c_calls.size(), 1u);
  EXPECT_EQ(rig.io.i2c_calls[0].address, 0x3C);
  EXPECT_EQ(rig.io.i2c_calls[0].bus, 0u);
  EXPECT_EQ(rig.io.i2c_calls[0].clock_hz, 400000u);
  // The STOP Wire sends after the NACK frees the bus: the next transfer goes through.
  EXPECT_EQ(wire.end_transmission({0x3F << 1, 0x05}, true), 0);
  ASSERT_EQ(rig.io.i2c_calls.size(), 2u);
  EXPECT_EQ(rig.io.i2c_calls[1].written, std::vector<uint8_t>{0x05});
}

TEST_F(Lpi2cTest, AWriteTakesItsWireTime) {
  wire.begin(400000);
  const SimTime before = rig.chip.now_ns();
  ASSERT_EQ(wire.end_transmission({0x3F << 1, 1, 2, 3, 4, 5, 6}, true), 0);
  const SimTime after = rig.chip.now_ns();
  ASSERT_EQ(rig.io.i2c_calls.size(), 1u);
  EXPECT_EQ(rig.io.i2c_calls[0].written, (std::vector<uint8_t>{1, 2, 3, 4, 5, 6}));
  // The device is asked once the address is out (START + 8 bits + ACK = 10 bits of 2.5 µs).
  EXPECT_GE(rig.io.i2c_calls[0].at_ns - before, 25000);
  // Wire sees the STOP after START + address (10 bits), six bytes (9 bits each) and the STOP
  // (1 bit): 162.5 µs at 400 kHz, plus its own polling.
  EXPECT_GE(after - before, 162500);
  EXPECT_LT(after - before, 200000);
}

TEST_F(Lpi2cTest, WriteThenReadWithRepeatedStartReadsTheDevice) {
  wire1.begin(400000);
  ASSERT_EQ(wire1.end_transmission({0x3F << 1, 0x07}, false), 0);  // register pointer, no STOP
  const std::vector<uint8_t> got = wire1.request_from(0x3F, 3);
  EXPECT_EQ(got, (std::vector<uint8_t>{0x11, 0x22, 0x33}));
  ASSERT_EQ(rig.io.i2c_calls.size(), 2u);
  EXPECT_EQ(rig.io.i2c_calls[0].bus, 1u);
  EXPECT_EQ(rig.io.i2c_calls[0].written, std::vector<uint8_t>{0x07});
  EXPECT_EQ(rig.io.i2c_calls[1].read_length, 3u);
}

TEST_F(Lpi2cTest, AWriteWithoutStopToAnAbsentAddressIsNackedBeforeTheRead) {
  wire.begin(400000);
  EXPECT_EQ(wire.end_transmission({0x50 << 1, 0x00}, false), 2);
  EXPECT_TRUE(wire.request_from(0x50, 2).empty());
}

// Where the FIFO stops on a NACK tells an address NACK from a data NACK (RM §47.3: the master
// halts at the NACKed byte): the commands behind it stay queued.
TEST_F(Lpi2cTest, ANackHaltsTheFifoAtTheNackedByte) {
  rig.io.i2c_results[0x21] = 4;  // the device at 0x21 refuses data
  wire.begin(400000);
  for (const auto& [address, left] : {std::pair<uint8_t, uint32_t>{0x20, 3}, {0x21, 1}}) {
    ASSERT_TRUE(wire.wait_idle());
    wire.set(kMtdr, kCmdStart | (address << 1));
    wire.set(kMtdr, kCmdTransmit | 0xA0);
    wire.set(kMtdr, kCmdTransmit | 0xA1);
    wire.set(kMtdr, kCmdStop);
    rig.run_until(rig.chip.now_ns() + 200000);
    EXPECT_TRUE(wire.reg(kMsr) & kNdf) << int(address);
    EXPECT_EQ(wire.reg(kMfsr) & 7u, left) << int(address);
    wire.set(kMcr, wire.reg(kMcr) | (1u << 8) | (1u << 9));  // Wire: reset the FIFOs, then STOP
    wire.set(kMtdr, kCmdStop);
    EXPECT_EQ(wire.reg(kMfsr) & 7u, 1u);
  }
  rig.run_until(rig.chip.now_ns() + 10000);
  EXPECT_FALSE(wire.reg(kMsr) & kBbf) << "the STOP went out: the bus is free";
}

TEST_F(Lpi2cTest, UnexpectedUsesAreRefused) {
  EXPECT_FALSE(rig.write(kLpi2c1 + kMier, 1)) << "interrupts";
  EXPECT_FALSE(rig.write(kLpi2c1 + kMcfgr1, 1u << 8)) << "AUTOSTOP";
  EXPECT_FALSE(rig.write(kLpi2c1 + kMtdr, 5u << 8)) << "START expecting NACK";
  uint32_t value = 0;
  EXPECT_FALSE(rig.read(kLpi2c1 + 0x110, value)) << "slave control register";
  EXPECT_FALSE(rig.read(kLpi2c1 + kMsr, value, 2)) << "16-bit access";
}

}  // namespace
}  // namespace stepdance::sim::image
