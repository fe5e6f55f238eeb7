// CCM, CCM_ANALOG and DCDC driven as Teensyduino 1.59's startup drives them (startup.c
// usb_pll_start, clockspeed.c set_arm_clock), with expectations from the reference manual.
#include "image/rt1062/ccm.hpp"

#include <gtest/gtest.h>

#include "fake_chip.hpp"
#include "image/chip/peripheral_bus.hpp"
#include "image/rt1062/dcdc.hpp"

namespace stepdance::sim::image::rt1062 {
namespace {

// Addresses (RM table 2-2 and §14.7, §14.8, §18.6).
constexpr uint32_t kCcm = 0x400FC000u, kAnalog = 0x400D8000u, kDcdc = 0x40080000u;
constexpr uint32_t kCbcdr = kCcm + 0x14, kCbcmr = kCcm + 0x18, kCacrr = kCcm + 0x10, kCscmr1 = kCcm + 0x1C,
                   kCdhipr = kCcm + 0x48, kCcgr1 = kCcm + 0x6C, kCcgr6 = kCcm + 0x80;
constexpr uint32_t kPllArm = kAnalog + 0x00, kPllUsb1 = kAnalog + 0x10, kPllUsb1Set = kAnalog + 0x14,
                   kPllUsb1Clr = kAnalog + 0x18, kPfd480 = kAnalog + 0xF0, kMisc0Set = kAnalog + 0x154;
constexpr uint32_t kLock = 1u << 31;

class ClockChip : public ::testing::Test {
 protected:
  ClockChip() : analog(chip), ccm(chip, analog) {
    window.add(analog);
    window.add(pmu);
    EXPECT_TRUE(bus.add(ccm));
    EXPECT_TRUE(bus.add(window));
    EXPECT_TRUE(bus.add(dcdc));
    bus.set_gate_query([this](ClockGate gate) { return ccm.gate_on(gate); });
    ccm.add_rates_listener([this](const ClockRates& rates) { reported.push_back(rates); });
  }
  uint32_t rd(uint32_t address) {
    uint32_t value = 0;
    BusRefusal refusal;
    EXPECT_TRUE(bus.read(address, 4, value, refusal)) << refusal.describe();
    return value;
  }
  void wr(uint32_t address, uint32_t value) {
    BusRefusal refusal;
    EXPECT_TRUE(bus.write(address, 4, value, refusal)) << refusal.describe();
  }
  // One pass of a polling loop: 1 µs of simulated time, as a CPU spinning on a register spends it.
  void spin() { chip.advance_to(chip.now_ns() + kMicrosecond); }

  testing::FakeChip chip;
  CcmAnalog analog;
  Ccm ccm;
  Pmu pmu;
  AnalogWindow window;
  Dcdc dcdc;
  PeripheralBus bus;
  std::vector<ClockRates> reported;
};

TEST_F(ClockChip, ResetValuesAreTheManuals) {
  EXPECT_EQ(rd(kCbcdr), 0x000A8300u);           // RM §14.7.5
  EXPECT_EQ(rd(kCbcmr), 0x2DAE8324u);           // RM §14.7.6
  EXPECT_EQ(rd(kCcm + 0x70), 0xFC3FFFFFu);      // CCGR2, RM §14.7.23
  EXPECT_EQ(rd(kCcm + 0x74), 0xFFFFFFCFu);      // CCGR3, RM §14.7.24
  EXPECT_EQ(rd(kPllArm), 0x00013063u);          // RM §14.8.1: bypassed, powered down, DIV 99
  EXPECT_EQ(rd(kPllUsb1), 0x00012000u);         // RM §14.8.2
  EXPECT_EQ(rd(kPllUsb1Set), 0x00012000u);      // an alias reads the register
  EXPECT_EQ(rd(kPfd480), 0x1311100Cu);          // RM §14.8.15
  EXPECT_EQ(rd(kDcdc + 0x0C), 0x0000010Eu);     // DCDC_REG3, RM §18.6.4: TRG 14 = 1.15 V
  EXPECT_EQ(rd(kAnalog + 0x120), 0x00000F74u);  // PMU_REG_3P0, RM §13.4.2
  // At reset the core runs from PLL1's 24 MHz bypass through ARM_PODF = 1 (÷2): 12 MHz;
  // IPG = ÷4 (IPG_PODF 3) = 3 MHz; PERCLK = IPG ÷ 1.
  EXPECT_EQ(ccm.core_clock_hz(), 12000000u);
  EXPECT_EQ(ccm.ipg_clock_hz(), 3000000u);
  ASSERT_EQ(reported.size(), 1u);
  EXPECT_EQ(reported[0].core_hz, 12000000u);
}

TEST_F(ClockChip, AnUnmodelledCcmRegisterIsRefusedNotZero) {
  uint32_t value = 0;
  BusRefusal refusal;
  EXPECT_FALSE(bus.read(kCcm + 0x04, 4, value, refusal));  // reserved in RM §14.7
  EXPECT_EQ(refusal.kind, BusRefusal::Kind::kUnmodelled);
  EXPECT_FALSE(bus.read(kAnalog + 0x1A0, 4, value, refusal));  // USB_ANALOG: not ours
  EXPECT_EQ(refusal.kind, BusRefusal::Kind::kUnmodelled);
}

TEST_F(ClockChip, UsbPllStartEndsWithTheUsbPllLockedAfterItsLockTime) {
  wr(kMisc0Set, 1u << 3);  // startup.c: PMU_MISC0_SET = 1<<3
  EXPECT_EQ(rd(kAnalog + 0x150), 0x04000008u);
  SimTime powered_at = -1, locked_seen = -1;
  for (int pass = 0; pass < 1000; ++pass) {  // Teensyduino's usb_pll_start, step for step
    const uint32_t n = rd(kPllUsb1);
    if (n & (1u << 1)) {
      wr(kPllUsb1Clr, 0xC000);
      wr(kPllUsb1Set, 1u << 16);
      wr(kPllUsb1Clr, (1u << 12) | (1u << 1) | (1u << 13) | (1u << 6));
    } else if (!(n & (1u << 13))) {
      wr(kPllUsb1Set, 1u << 13);
    } else if (!(n & (1u << 12))) {
      wr(kPllUsb1Set, 1u << 12);
      powered_at = chip.now_ns();
    } else if (!(n & kLock)) {
      spin();
      continue;
    } else if (n & (1u << 16)) {
      if (locked_seen < 0) locked_seen = chip.now_ns();
      wr(kPllUsb1Clr, 1u << 16);
    } else if (!(n & (1u << 6))) {
      wr(kPllUsb1Set, 1u << 6);
    } else {
      break;
    }
    spin();
  }
  EXPECT_EQ(rd(kPllUsb1), kLock | (1u << 13) | (1u << 12) | (1u << 6));
  // Lock after 383 cycles of 24 MHz = 15.958 µs (data sheet); the loop sees it within 1 µs.
  ASSERT_GE(powered_at, 0);
  EXPECT_GE(locked_seen - powered_at, 15958);
  EXPECT_LE(locked_seen - powered_at, 15958 + 2 * kMicrosecond);
  EXPECT_EQ(analog.pll_hz(Pll::kUsb1), 480000000u);
  // reset_PFD: PFD0 = 480 × 18 / 12 = 720 MHz.
  wr(kAnalog + 0xF4, 0x80808080u);
  wr(kPfd480, 0x13110D0Cu);
  EXPECT_EQ(analog.pfd_hz(Pll::kUsb1, 0), 720000000u);
}

TEST_F(ClockChip, SetArmClock600MHzGivesThe600MHzCoreAnd150MHzIpg) {
  wr(kPllUsb1Set, 1u << 12);  // the USB PLL as usb_pll_start leaves it
  chip.advance_to(100 * kMicrosecond);
  wr(kPllUsb1Clr, 1u << 16);
  wr(kPllUsb1Set, 1u << 6);
  wr(kCscmr1, (rd(kCscmr1) & ~0x3Fu) | (1u << 6));  // startup.c: PERCLK from the 24 MHz oscillator

  wr(kCcgr6, rd(kCcgr6) | (3u << 6));  // DCDC gate
  uint32_t dcdc_reg3 = rd(kDcdc + 0x0C);
  EXPECT_LT(dcdc_reg3 & 0x1Fu, (1250u - 800u) / 25u);  // 1.15 V < 1.25 V: raise it first
  dcdc_reg3 = (dcdc_reg3 & ~0x1Fu) | ((1250u - 800u) / 25u);
  wr(kDcdc + 0x0C, dcdc_reg3);
  EXPECT_TRUE(rd(kDcdc) & (1u << 31));  // STS_DC_OK
  EXPECT_EQ(dcdc.core_millivolts(), 1250u);

  uint32_t cbcdr = rd(kCbcdr);
  cbcdr = (cbcdr & ~(7u << 27)) | (3u << 27);  // PERIPH_CLK2_PODF = ÷4
  wr(kCbcdr, cbcdr);
  cbcdr |= 1u << 25;  // PERIPH_CLK_SEL = PERIPH_CLK2 (PLL3 480 MHz ÷ 4)
  wr(kCbcdr, cbcdr);
  EXPECT_EQ(rd(kCdhipr), 0u);
  EXPECT_EQ(ccm.core_clock_hz(), 120000000u);

  wr(kPllArm, 1u << 12);           // POWERDOWN
  wr(kPllArm, (1u << 13) | 100u);  // ENABLE, DIV_SELECT 100
  const SimTime started = chip.now_ns();
  while (!(rd(kPllArm) & kLock)) spin();  // lock after 2250 / 24 MHz = 93.75 µs
  EXPECT_GE(chip.now_ns() - started, 93750);
  EXPECT_LE(chip.now_ns() - started, 93750 + kMicrosecond);
  wr(kCacrr, 1);                             // ARM_PODF = ÷2
  cbcdr = (cbcdr & ~(3u << 8)) | (3u << 8);  // IPG_PODF = ÷4
  wr(kCbcdr, cbcdr);
  wr(kCbcdr, rd(kCbcdr) & ~(1u << 25));  // back to PRE_PERIPH = PLL1 ÷ ARM_PODF

  // 24 MHz × 100 / 2 = 1200 MHz; ÷2 = 600 MHz core; ÷4 = 150 MHz IPG; PERCLK = 24 MHz.
  EXPECT_EQ(ccm.core_clock_hz(), 600000000u);
  EXPECT_EQ(ccm.ipg_clock_hz(), 150000000u);
  EXPECT_EQ(ccm.perclk_hz(), 24000000u);
  ASSERT_FALSE(reported.empty());
  EXPECT_EQ(reported.back().core_hz, 600000000u);
}

// The CI stand-in core's clock start (targets/teensy/stand-in/clocks.cpp): the switch-over runs
// from the 24 MHz oscillator (PERIPH_CLK2_SEL 1) instead of PLL3.
TEST_F(ClockChip, StandInClockStartGives600MHzThroughTheOscillator) {
  wr(kCscmr1, (rd(kCscmr1) & ~0x3Fu) | (1u << 6));
  wr(kCcgr6, rd(kCcgr6) | (3u << 6));
  wr(kDcdc + 0x0C, (rd(kDcdc + 0x0C) & ~0x1Fu) | 18u);
  ASSERT_TRUE(rd(kDcdc) & (1u << 31));
  wr(kCbcdr, rd(kCbcdr) & ~(7u << 27));
  wr(kCbcmr, (rd(kCbcmr) & ~(3u << 12)) | (1u << 12));
  wr(kCbcdr, rd(kCbcdr) | (1u << 25));
  EXPECT_EQ(ccm.core_clock_hz(), 24000000u);  // oscillator ÷ 1 ÷ AHB 1
  wr(kPllArm, 1u << 12);
  wr(kPllArm, (1u << 13) | 100u);
  while (!(rd(kPllArm) & kLock)) spin();
  wr(kCacrr, 1);
  wr(kCbcdr, rd(kCbcdr) & ~(7u << 10));
  wr(kCbcdr, (rd(kCbcdr) & ~(3u << 8)) | (3u << 8));
  wr(kCbcmr, rd(kCbcmr) | (3u << 18));
  wr(kCbcdr, rd(kCbcdr) & ~(1u << 25));
  EXPECT_EQ(ccm.core_clock_hz(), 600000000u);
  EXPECT_EQ(ccm.ipg_clock_hz(), 150000000u);
  EXPECT_EQ(ccm.perclk_hz(), 24000000u);
}

TEST_F(ClockChip, ABlockWhoseGateIsOffIsRefused) {
  uint32_t value = 0;
  BusRefusal refusal;
  wr(kCcgr6, rd(kCcgr6) & ~(3u << 6));  // DCDC gate off
  EXPECT_FALSE(bus.read(kDcdc, 4, value, refusal));
  EXPECT_EQ(refusal.kind, BusRefusal::Kind::kGateOff);
  EXPECT_EQ(refusal.gate.ccgr, 6);
  EXPECT_EQ(refusal.gate.field, 3);
  wr(kCcgr6, rd(kCcgr6) | (1u << 6));  // 01: on in run mode only — still on for the CPU
  EXPECT_TRUE(bus.read(kDcdc, 4, value, refusal));
  EXPECT_TRUE(ccm.gate_on(ClockGate{1, 8}));  // ADC1 (CCGR1 CG8) is on at reset
  wr(kCcgr1, rd(kCcgr1) & ~(3u << 16));
  EXPECT_FALSE(ccm.gate_on(ClockGate{1, 8}));
}

TEST_F(ClockChip, PllLockIsLostOnPowerDownAndTheCoreClockFollows) {
  wr(kPllArm, (1u << 13) | 88u);            // 24 × 88 / 2 = 1056 MHz
  EXPECT_EQ(analog.pll_hz(Pll::kArm), 0u);  // not yet locked
  chip.advance_to(chip.now_ns() + 100 * kMicrosecond);
  EXPECT_EQ(analog.pll_hz(Pll::kArm), 1056000000u);
  // The lock event told the CCM: the core (PLL1 ÷ 2 at reset's ARM_PODF) became 528 MHz.
  EXPECT_EQ(reported.back().core_hz, 528000000u);
  wr(kPllArm, (1u << 13) | (1u << 12) | 88u);
  EXPECT_FALSE(rd(kPllArm) & kLock);
  EXPECT_EQ(ccm.core_clock_hz(), 0u);
}

}  // namespace
}  // namespace stepdance::sim::image::rt1062
