// The CI stand-in core's start-up steps and Arduino functions, run on the register model.
//
// Expected values come from the manuals, not from the stand-in: reset values and field layouts of
// the i.MX RT1060 reference manual (RM, IMXRT1060RM rev 3), the clock-tree arithmetic of RM
// §14 (Fout = 24 MHz × DIV_SELECT / 2, then the PODF dividers), the ARMv7-M MPU and SysTick
// encodings, the pad and ADC-input tables of the RM, and Arduino's documented Print output.
#include <Arduino.h>
#include <avr/eeprom.h>
#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "register_model.hpp"
#include "stand_in_hooks.h"
#include "stand_in_startup.h"

extern "C" {
alignas(32) uint32_t _stack_guard[8];  // the linker script's symbol, here an aligned host array
}

namespace {

// ---- Addresses, from the RM and the ARMv7-M ARM (written out here, not taken from the stand-in) --
constexpr uint32_t kPllArm = 0x400D8000, kPllUsb1 = 0x400D8010, kPllUsb1Set = 0x400D8014, kPllUsb1Clr = 0x400D8018;
constexpr uint32_t kCacrr = 0x400FC010, kCbcdr = 0x400FC014, kCbcmr = 0x400FC018, kCscmr1 = 0x400FC01C;
constexpr uint32_t kDcdcReg0 = 0x40080000, kDcdcReg3 = 0x4008000C;
constexpr uint32_t kSystCsr = 0xE000E010, kSystRvr = 0xE000E014, kSystCvr = 0xE000E018, kIcsr = 0xE000ED04;

/// Plays the analog PLLs: LOCK follows ENABLE (ARM PLL) or POWER (USB1 PLL); SET/CLR aliases act on
/// the register (RM §14.8). The DCDC reports settled at once.
void play_clock_hardware() {
  teensy_model::reset();
  teensy_model::poke(kCacrr, 0x00000001);    // RM §14.7.4 reset values
  teensy_model::poke(kCbcdr, 0x000A8300);    // §14.7.5
  teensy_model::poke(kCbcmr, 0x2DAE8324);    // §14.7.6
  teensy_model::poke(kCscmr1, 0x04900000);   // §14.7.7
  teensy_model::poke(kPllArm, 0x00013063);   // §14.8.1
  teensy_model::poke(kPllUsb1, 0x00012000);  // §14.8.2
  teensy_model::on_read(kPllArm, [](uint32_t v) { return (v & (1u << 13)) ? v | 1u << 31 : v & ~(1u << 31); });
  teensy_model::on_read(kPllUsb1, [](uint32_t v) { return (v & (1u << 12)) ? v | 1u << 31 : v & ~(1u << 31); });
  teensy_model::on_write(kPllUsb1Set, [](uint32_t, uint32_t w) {
    teensy_model::poke(kPllUsb1, teensy_model::peek(kPllUsb1) | w);
    return 0u;
  });
  teensy_model::on_write(kPllUsb1Clr, [](uint32_t, uint32_t w) {
    teensy_model::poke(kPllUsb1, teensy_model::peek(kPllUsb1) & ~w);
    return 0u;
  });
  teensy_model::on_read(kDcdcReg0, [](uint32_t v) { return v | 1u << 31; });
}

/// Indexes in the log of the writes of `value` (under `mask`) to `address`.
std::vector<int> writes(uint32_t address, uint32_t mask, uint32_t value) {
  std::vector<int> found;
  const auto& log = teensy_model::log();
  for (size_t i = 0; i < log.size(); ++i) {
    if (log[i].kind == teensy_model::Access::kWrite && log[i].address == address && (log[i].value & mask) == value) {
      found.push_back(static_cast<int>(i));
    }
  }
  return found;
}
int first_write(uint32_t address, uint32_t mask, uint32_t value) {
  const std::vector<int> found = writes(address, mask, value);
  return found.empty() ? -1 : found.front();
}
int last_write(uint32_t address, uint32_t mask, uint32_t value) {
  const std::vector<int> found = writes(address, mask, value);
  return found.empty() ? -1 : found.back();
}

TEST(StandInClocks, CoreRunsAt600MHzAndBusAt150MHzFromTheRegisters) {
  play_clock_hardware();
  stand_in_clocks_start();
  const uint32_t pll = teensy_model::peek(kPllArm);
  EXPECT_EQ(pll & ((1u << 12) | (1u << 16)), 0u) << "PLL1 powered and not bypassed";
  EXPECT_NE(pll & (1u << 13), 0u) << "PLL1 output enabled";
  const uint32_t cbcdr = teensy_model::peek(kCbcdr);
  const uint32_t cbcmr = teensy_model::peek(kCbcmr);
  EXPECT_EQ(cbcdr & (1u << 25), 0u) << "periph_clk from pre_periph_clk";
  EXPECT_EQ((cbcmr >> 18) & 3u, 3u) << "pre_periph_clk = divided PLL1";
  const uint64_t pll_hz = 24000000ull * (pll & 0x7Fu) / 2;
  const uint64_t core_hz = pll_hz / ((teensy_model::peek(kCacrr) & 7u) + 1) / (((cbcdr >> 10) & 7u) + 1);
  const uint64_t ipg_hz = core_hz / (((cbcdr >> 8) & 3u) + 1);
  EXPECT_EQ(core_hz, 600000000u);
  EXPECT_EQ(ipg_hz, 150000000u);
  EXPECT_EQ(F_CPU_ACTUAL, 600000000u);
  EXPECT_EQ(F_BUS_ACTUAL, 150000000u);
  EXPECT_EQ(teensy_model::peek(kCscmr1) & 0x7Fu, 0x40u) << "PERCLK = 24 MHz oscillator / 1";
}

TEST(StandInClocks, VoltageRisesAndCoreLeavesPll1BeforeItIsReprogrammed) {
  play_clock_hardware();
  stand_in_clocks_start();
  const int voltage = first_write(kDcdcReg3, 0x1F, 18);  // 0.8 V + 18 × 25 mV = 1.25 V
  const int to_oscillator = first_write(kCbcdr, 1u << 25, 1u << 25);
  const int pll_changed = first_write(kPllArm, 0x7F, 100);
  const int back_to_pll = last_write(kCbcdr, 1u << 25, 0);
  ASSERT_GE(voltage, 0);
  ASSERT_GE(to_oscillator, 0);
  ASSERT_GE(pll_changed, 0);
  ASSERT_GE(back_to_pll, 0);
  EXPECT_LT(voltage, to_oscillator);
  EXPECT_LT(to_oscillator, pll_changed);
  EXPECT_LT(pll_changed, back_to_pll);
  EXPECT_EQ((teensy_model::peek(kCbcmr) >> 12) & 3u, 1u) << "periph_clk2 = oscillator while PLL1 relocks";
}

TEST(StandInClocks, UsbPllEndsAt480MHzWithItsUsbClocksOn) {
  play_clock_hardware();
  stand_in_usb_pll_start();
  const uint32_t pll = teensy_model::peek(kPllUsb1);
  EXPECT_EQ(pll & ((1u << 1) | (1u << 16)), 0u) << "DIV_SELECT 0 (×20 = 480 MHz), not bypassed";
  EXPECT_EQ(pll & ((1u << 6) | (1u << 12) | (1u << 13)), (1u << 6) | (1u << 12) | (1u << 13));
}

// ---- SysTick time ------------------------------------------------------------------------------

void start_time() {
  play_clock_hardware();
  stand_in_clocks_start();
  stand_in_systick_start();
}

TEST(StandInTime, SysTickReloadsEveryMillisecondOfTheCoreClock) {
  start_time();
  EXPECT_EQ(teensy_model::peek(kSystRvr), 600000u - 1u);
  EXPECT_EQ(teensy_model::peek(kSystCsr), 7u) << "ENABLE, TICKINT, CLKSOURCE = processor clock";
  EXPECT_EQ(teensy_model::peek(0xE000ED20) >> 24, 32u) << "SysTick priority 32 (SHPR3)";
}

TEST(StandInTime, MicrosAddsTheCountedDownCyclesToTheMilliseconds) {
  start_time();
  const uint32_t before = millis();
  for (int i = 0; i < 7; ++i) stand_in_systick_isr();
  EXPECT_EQ(millis(), before + 7u);
  teensy_model::poke(kSystCvr, 599999u - 300u * 600u);  // 300 µs after the last wrap
  EXPECT_EQ(micros(), (before + 7u) * 1000u + 300u);
}

TEST(StandInTime, MicrosCountsAWrapThatSysTickHasNotHandledYet) {
  start_time();
  const uint32_t before = millis();
  teensy_model::poke(kSystCvr, 599999u - 1200u);  // 2 µs after a wrap...
  teensy_model::poke(kIcsr, 1u << 26);            // ...whose exception is still pending
  EXPECT_EQ(micros(), (before + 1u) * 1000u + 2u);
  teensy_model::poke(kSystCvr, 10u);  // pending, but the counter was read before that wrap
  EXPECT_EQ(micros(), before * 1000u + (599999u - 10u) / 600u);
}

// ---- Pins and analog input -------------------------------------------------------------------

TEST(StandInPins, PinModeMuxesThePadToGpioAndSetsTheDirection) {
  teensy_model::reset();
  pinMode(13, OUTPUT);  // pin 13 = GPIO_B0_03 = GPIO2/GPIO7 bit 3
  EXPECT_EQ(teensy_model::peek(0x401F8148), 0x15u) << "SW_MUX_CTL_PAD_GPIO_B0_03: ALT5 | SION";
  EXPECT_EQ(teensy_model::peek(0x42004004) & (1u << 3), 1u << 3) << "GPIO7_GDIR bit 3";
  digitalWrite(13, HIGH);
  EXPECT_EQ(teensy_model::peek(0x42004084), 1u << 3) << "GPIO7_DR_SET";
  digitalWrite(13, LOW);
  EXPECT_EQ(teensy_model::peek(0x42004088), 1u << 3) << "GPIO7_DR_CLEAR";
  pinMode(2, INPUT_PULLUP);  // pin 2 = GPIO_EMC_04 = GPIO4/GPIO9 bit 4
  EXPECT_EQ(teensy_model::peek(0x401F8014 + 0x1F0 + 16), 0x1F000u) << "PKE | PUE | PUS 22k up | HYS";
  EXPECT_EQ(teensy_model::peek(0x4200C004) & (1u << 4), 0u) << "GPIO9_GDIR bit 4 = input";
  digitalWrite(2, LOW);  // on an input: the 100 kΩ pull-down instead, and DR untouched
  EXPECT_EQ(teensy_model::peek(0x401F8014 + 0x1F0 + 16), 0x13000u) << "PKE | PUE | PUS 100k down | HYS";
  EXPECT_EQ(teensy_model::peek(0x4200C088), 0u) << "GPIO9_DR_CLEAR not written";
  teensy_model::poke(0x4200C008, 1u << 4);  // GPIO9_PSR
  EXPECT_EQ(digitalRead(2), HIGH);
  teensy_model::poke(0x4200C008, 0);
  EXPECT_EQ(digitalRead(2), LOW);
}

TEST(StandInAnalog, EachAnalogPinConvertsItsAdcInput) {
  struct Input {
    uint8_t pin;
    uint32_t adc_base;
    uint32_t channel;
  };
  // RM ADC external signals: ADC1_IN0 = AD_B1_11, IN1/2 = AD_B0_12/13, IN5..15 = AD_B1_00..10;
  // ADC2 IN1..4 = AD_B1_12..15. Teensy 4.1 pins to pads from its schematic.
  const Input inputs[] = {{14, 0x400C4000, 7},  {15, 0x400C4000, 8},  {16, 0x400C4000, 12}, {17, 0x400C4000, 11},
                          {18, 0x400C4000, 6},  {19, 0x400C4000, 5},  {20, 0x400C4000, 15}, {21, 0x400C4000, 0},
                          {22, 0x400C4000, 13}, {23, 0x400C4000, 14}, {24, 0x400C4000, 1},  {25, 0x400C4000, 2},
                          {26, 0x400C8000, 3},  {27, 0x400C8000, 4},  {38, 0x400C8000, 1},  {39, 0x400C8000, 2},
                          {40, 0x400C4000, 9},  {41, 0x400C4000, 10}};
  for (const Input& input : inputs) {
    teensy_model::reset();
    teensy_model::poke(input.adc_base + 0x20, 1);      // HS.COCO0: conversion done
    teensy_model::poke(input.adc_base + 0x24, 0x2A5);  // R0
    EXPECT_EQ(analogRead(input.pin), 0x2A5) << "pin " << int(input.pin);
    EXPECT_EQ(teensy_model::peek(input.adc_base), input.channel) << "pin " << int(input.pin) << ": HC0.ADCH";
  }
  teensy_model::reset();
  EXPECT_EQ(analogRead(0), 0) << "pin 0 has no ADC input";
  EXPECT_TRUE(teensy_model::log().empty());
}

TEST(StandInAnalog, StartUpCalibratesBothAdcsIn10BitMode) {
  teensy_model::reset();
  for (uint32_t base : {0x400C4000u, 0x400C8000u}) {
    teensy_model::on_read(base + 0x48, [](uint32_t v) { return v & ~(1u << 7); });  // CAL done at once
    teensy_model::write_one_to_clear(base + 0x4C);
  }
  teensy_model::poke(0x400C804C, 1u << 1);                                         // ADC2 reports CALF
  teensy_model::on_write(0x400C804C, [](uint32_t, uint32_t) { return 1u << 1; });  // and keeps it
  stand_in_analog_start();
  EXPECT_EQ((teensy_model::peek(0x400C4044) >> 2) & 3u, 1u) << "ADC1 CFG.MODE = 10-bit";
  EXPECT_NE(first_write(0x400C4048, 1u << 7, 1u << 7), -1) << "ADC1 GC.CAL started";
  EXPECT_NE(first_write(0x400C8048, 1u << 7, 1u << 7), -1) << "ADC2 GC.CAL started";
  EXPECT_EQ(stand_in_adc_calibration_failed, 2u) << "ADC2 failed, ADC1 did not";
}

// ---- MPU regions (ARMv7-M ARM §B3.5: RBAR = base | VALID | region, RASR fields) -----------------

TEST(StandInMemoryProtection, RegionsAreTeensysWithAStackGuard) {
  teensy_model::reset();
  stand_in_memory_protection_start();
  std::vector<std::pair<uint32_t, uint32_t>> regions;  // (RBAR, RASR) as written
  const auto& log = teensy_model::log();
  for (size_t i = 0; i + 1 < log.size(); ++i) {
    if (log[i].address == 0xE000ED9C && log[i + 1].address == 0xE000EDA0)
      regions.emplace_back(log[i].value, log[i + 1].value);
  }
  ASSERT_EQ(regions.size(), 9u);
  EXPECT_EQ(regions[0], std::make_pair(0x00000010u, 0x1000003Fu)) << "4 GB, XN, no access";
  EXPECT_EQ(regions[2], std::make_pair(0x00000012u, 0x10100009u)) << "32 B null trap, device, no access";
  EXPECT_EQ(regions[4], std::make_pair(0x20000014u, 0x13080025u)) << "DTCM 512 KB, normal uncached, RW, XN";
  const uint32_t guard = static_cast<uint32_t>(reinterpret_cast<uintptr_t>(_stack_guard));
  EXPECT_EQ(regions[5], std::make_pair(guard | 0x15u, 0x10000009u)) << "32 B stack guard, no access";
  EXPECT_EQ(regions[8], std::make_pair(0x60000018u, 0x070B002Fu)) << "flash 16 MB, WBWA, read-only";
  EXPECT_EQ(teensy_model::peek(0xE000ED94), 1u) << "MPU on";
  EXPECT_EQ(teensy_model::peek(0xE000ED14) & (3u << 16), 3u << 16) << "CCR.DC and CCR.IC";
}

// ---- EEPROM emulation and Print -----------------------------------------------------------------

TEST(StandInEeprom, FreshBytesReadErasedAndWritesReadBack) {
  uint8_t bytes[4] = {};
  eeprom_read_block(bytes, reinterpret_cast<const void*>(100), 4);
  EXPECT_EQ(bytes[0], 0xFF);
  EXPECT_EQ(bytes[3], 0xFF);
  const uint8_t written[3] = {1, 0, 0xFE};
  eeprom_write_block(written, reinterpret_cast<void*>(E2END - 1), 3);  // the last one falls off the end
  eeprom_read_block(bytes, reinterpret_cast<const void*>(E2END - 1), 3);
  EXPECT_EQ(bytes[0], 1);
  EXPECT_EQ(bytes[1], 0);
  EXPECT_EQ(bytes[2], 0xFF);
}

class StringPrint : public Print {
 public:
  size_t write(uint8_t byte) override {
    text += static_cast<char>(byte);
    return 1;
  }
  using Print::write;
  std::string text;
};

TEST(StandInPrint, FormatsAsArduinoDocuments) {
  StringPrint out;
  out.print(-42);
  out.print(' ');
  out.print(255, HEX);
  out.print(' ');
  out.print(5u, 2);
  out.print(' ');
  out.print(3.14159, 2);
  out.print(' ');
  out.print(-0.005, 2);
  out.print(' ');
  out.print(2.5, 0);
  out.print(' ');
  out.print(1e10, 2);
  out.print(' ');
  out.println(std::numeric_limits<double>::infinity(), 2);
  EXPECT_EQ(out.text, "-42 FF 101 3.14 -0.01 3 ovf inf\r\n");
}

}  // namespace
