// The stand-in core's Wire on the register model, with a played LPI2C controller and device.
//
// Expected values: pad mux modes and input selects of RM §11.7 (ALT3 = LPI2C1 on GPIO_AD_B1_00/01,
// ALT1 = LPI2C3 on GPIO_AD_B1_07/06), the LPI2C command encoding of MTDR (CMD 10:8: 0 transmit,
// 1 receive DATA + 1 bytes, 2 stop, 4 start + address), Wire's documented endTransmission codes,
// and the I2C bus specification's timing (NXP UM10204, Table 10: fSCL and the minimum SCL low time).
#include <Arduino.h>
#include <Wire.h>
#include <gtest/gtest.h>

#include <deque>
#include <vector>

#include "register_model.hpp"

namespace {

constexpr uint32_t kLpi2c1 = 0x403F0000, kLpi2c3 = 0x403F8000;
constexpr uint32_t kMcr = 0x10, kMsr = 0x14, kMcfgr1 = 0x24, kMcfgr2 = 0x28, kMccr0 = 0x48, kMfsr = 0x5C, kMtdr = 0x60,
                   kMrdr = 0x70;

/// A controller whose FIFO drains at once, talking to one device: commands are recorded; the byte of
/// command `nack_at` (0 = the address) is not acknowledged, and commands after it stay in the FIFO.
struct PlayedBus {
  std::vector<uint32_t> commands;
  int nack_at = -1;
  std::deque<uint8_t> device_bytes;
};
PlayedBus bus;

void play_lpi2c(uint32_t base) {
  teensy_model::reset();
  bus = PlayedBus{};
  teensy_model::on_write(base + kMtdr, [](uint32_t, uint32_t w) {
    bus.commands.push_back(w);
    return w;
  });
  teensy_model::on_read(base + kMfsr, [](uint32_t) {
    if (bus.nack_at < 0 || bus.commands.size() <= static_cast<size_t>(bus.nack_at) + 1) return 0u;
    const size_t waiting = bus.commands.size() - static_cast<size_t>(bus.nack_at) - 1;
    return static_cast<uint32_t>(waiting > 4 ? 4 : waiting);  // TXCOUNT
  });
  teensy_model::on_read(base + kMsr, [](uint32_t) {
    if (bus.nack_at >= 0 && bus.commands.size() > static_cast<size_t>(bus.nack_at)) return 1u << 10;  // NDF
    if (!bus.commands.empty() && (bus.commands.back() >> 8) == 2) return 1u << 9;                     // SDF
    return 0u;
  });
  teensy_model::on_read(base + kMrdr, [](uint32_t) {
    if (bus.device_bytes.empty()) return 1u << 14;  // RXEMPTY
    const uint32_t byte = bus.device_bytes.front();
    bus.device_bytes.pop_front();
    return byte;
  });
}

TEST(StandInWire, BeginRoutesQwiicPadsToTheirLpi2c) {
  play_lpi2c(kLpi2c1);
  Wire.begin();
  EXPECT_EQ(teensy_model::peek(0x401F80FC), 0x13u) << "pin 19 GPIO_AD_B1_00: ALT3 LPI2C1_SCL | SION";
  EXPECT_EQ(teensy_model::peek(0x401F8100), 0x13u) << "pin 18 GPIO_AD_B1_01: ALT3 LPI2C1_SDA | SION";
  EXPECT_EQ(teensy_model::peek(0x401F84CC), 1u) << "LPI2C1_SCL_SELECT_INPUT";
  EXPECT_EQ(teensy_model::peek(0x401F84D0), 1u) << "LPI2C1_SDA_SELECT_INPUT";
  EXPECT_EQ(teensy_model::peek(0x400FC070) & (3u << 6), 3u << 6) << "CCGR2 CG3 (lpi2c1) on";
  EXPECT_EQ(teensy_model::peek(0x400FC038) & (0x7Fu << 18), 1u << 18) << "CSCDR2: 24 MHz oscillator, /1";
  EXPECT_EQ(teensy_model::peek(kLpi2c1 + kMcr), 1u) << "MCR.MEN";
  play_lpi2c(kLpi2c3);
  Wire1.begin();
  EXPECT_EQ(teensy_model::peek(0x401F8118), 0x11u) << "pin 16 GPIO_AD_B1_07: ALT1 LPI2C3_SCL | SION";
  EXPECT_EQ(teensy_model::peek(0x401F8114), 0x11u) << "pin 17 GPIO_AD_B1_06: ALT1 LPI2C3_SDA | SION";
  EXPECT_EQ(teensy_model::peek(0x401F84DC), 2u) << "LPI2C3_SCL_SELECT_INPUT";
  EXPECT_EQ(teensy_model::peek(0x401F84E0), 2u) << "LPI2C3_SDA_SELECT_INPUT";
  EXPECT_EQ(teensy_model::peek(0x400FC070) & (3u << 10), 3u << 10) << "CCGR2 CG5 (lpi2c3) on";
}

TEST(StandInWire, ClockMeetsTheI2cSpecification) {
  struct Mode {
    uint32_t hz;
    double min_low_us;  // UM10204 Table 10, tLOW
  };
  for (const Mode mode : {Mode{100000, 4.7}, Mode{400000, 1.3}, Mode{1000000, 0.5}}) {
    play_lpi2c(kLpi2c1);
    Wire.setClock(mode.hz);
    const uint32_t mccr0 = teensy_model::peek(kLpi2c1 + kMccr0);
    const uint32_t prescale = 1u << (teensy_model::peek(kLpi2c1 + kMcfgr1) & 7u);
    const uint32_t filter = (teensy_model::peek(kLpi2c1 + kMcfgr2) >> 16) & 0xFu;
    const uint32_t clklo = mccr0 & 0x3Fu, clkhi = (mccr0 >> 8) & 0x3Fu;
    // RM LPI2C timing: SCL period = (CLKHI + CLKLO + 2 + (2 + FILTSCL) / prescale) × prescale / 24 MHz.
    const double period_us = (clkhi + clklo + 2 + (2 + filter) / prescale) * prescale / 24.0;
    EXPECT_LE(1e6 / period_us, mode.hz * 1.0001) << mode.hz;
    EXPECT_GE(1e6 / period_us, mode.hz * 0.95) << mode.hz;
    EXPECT_GE((clklo + 1) * prescale / 24.0, mode.min_low_us) << mode.hz;
  }
}

TEST(StandInWire, WriteSendsStartAddressDataStop) {
  play_lpi2c(kLpi2c1);
  Wire.beginTransmission(0x20);
  const uint8_t data[2] = {0x12, 0x34};
  EXPECT_EQ(Wire.write(data, 2), 2u);
  EXPECT_EQ(Wire.endTransmission(1), 0);
  EXPECT_EQ(bus.commands, (std::vector<uint32_t>{0x400 | 0x40, 0x012, 0x034, 0x200}));
}

TEST(StandInWire, NacksReportWiresCodes) {
  play_lpi2c(kLpi2c1);
  bus.nack_at = 0;
  Wire.beginTransmission(0x21);
  const uint8_t data[6] = {1, 2, 3, 4, 5, 6};
  Wire.write(data, 6);
  EXPECT_EQ(Wire.endTransmission(1), 2) << "address not acknowledged";
  play_lpi2c(kLpi2c1);
  bus.nack_at = 2;
  Wire.beginTransmission(0x21);
  Wire.write(data, 6);
  EXPECT_EQ(Wire.endTransmission(1), 3) << "second data byte not acknowledged";
  play_lpi2c(kLpi2c1);
  Wire.beginTransmission(0x21);
  uint8_t too_many[TwoWire::kBufferBytes + 1] = {};
  EXPECT_EQ(Wire.write(too_many, sizeof(too_many)), TwoWire::kBufferBytes);
  EXPECT_EQ(Wire.endTransmission(1), 1) << "more than the buffer";
  EXPECT_TRUE(bus.commands.empty());
}

TEST(StandInWire, ReadReturnsTheDevicesBytes) {
  play_lpi2c(kLpi2c1);
  bus.device_bytes = {0xAB, 0xCD};
  EXPECT_EQ(Wire.requestFrom(0x36, 2, 1), 2);
  EXPECT_EQ(bus.commands, (std::vector<uint32_t>{0x400 | 0x6D, 0x100 | 1, 0x200}));
  EXPECT_EQ(Wire.available(), 2);
  EXPECT_EQ(Wire.read(), 0xAB);
  EXPECT_EQ(Wire.read(), 0xCD);
  EXPECT_EQ(Wire.read(), -1);
  play_lpi2c(kLpi2c1);
  bus.nack_at = 0;
  EXPECT_EQ(Wire.requestFrom(0x37, 2, 1), 0) << "nobody at 0x37";
}

}  // namespace
