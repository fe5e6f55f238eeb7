// Teensyduino 1.59's whole start-up (startup.c ResetHandler → main, with clockspeed.c, analog.c,
// pwm.c's quad timers, tempmon.c and usb.c's PMU/CCM writes), register access by register access,
// on the blocks add_clock_and_pin_blocks builds for a Teensy 4.1: every access is answered, the
// clocks end at 600/150/24 MHz, and the world sees no pin change.
#include <gtest/gtest.h>

#include "fake_chip.hpp"
#include "image/rt1062/clock_and_pin_blocks.hpp"

namespace stepdance::sim::image::rt1062 {
namespace {

constexpr uint32_t kGpr = 0x400AC000u, kCcm = 0x400FC000u, kAnalog = 0x400D8000u, kDcdc = 0x40080000u,
                   kPit = 0x40084000u, kSnvs = 0x400D4000u, kIomuxc = 0x401F8000u, kFlexspi2 = 0x402A4000u,
                   kAdc1 = 0x400C4000u, kAdc2 = 0x400C8000u;

class Startup : public ::testing::Test {
 protected:
  Startup() : blocks(add_clock_and_pin_blocks(bus, chip, world, TeensyModel::kTeensy41)) {}
  uint32_t rd(uint32_t address, uint8_t bytes = 4) {
    uint32_t value = 0;
    BusRefusal refusal;
    EXPECT_TRUE(bus.read(address, bytes, value, refusal)) << refusal.describe();
    return value;
  }
  void wr(uint32_t address, uint32_t value, uint8_t bytes = 4) {
    BusRefusal refusal;
    EXPECT_TRUE(bus.write(address, bytes, value, refusal)) << refusal.describe();
  }
  void spin() { chip.advance_to(chip.now_ns() + 100); }  // a polling pass: ~60 instructions

  void reset_handler() {
    wr(kGpr + 0x44, 0xAAAAAAAFu);  // GPR17 = _flexram_bank_config (a linker-chosen value)
    wr(kGpr + 0x40, 0x00200007u);  // GPR16
    wr(kGpr + 0x38, 0x00AA0000u);  // GPR14: 512 KB ITCM and DTCM
    wr(kAnalog + 0x154, 1u << 3);  // PMU_MISC0_SET
    reset_pfd();
    wr(kCcm + 0x1C, (rd(kCcm + 0x1C) & ~0x3Fu) | (1u << 6));                // CSCMR1
    wr(kCcm + 0x24, (rd(kCcm + 0x24) & ~0x3Fu) | (1u << 6));                // CSCDR1
    for (uint32_t n = 0; n < 4; ++n) wr(kGpr + 0x68 + 4 * n, 0xFFFFFFFFu);  // GPR26..29
  }
  void reset_pfd() {
    wr(kAnalog + 0x104, 0x80808080u);
    wr(kAnalog + 0x100, 0x2018101Bu);
    wr(kAnalog + 0xF4, 0x80808080u);
    wr(kAnalog + 0xF0, 0x13110D0Cu);
  }
  void usb_pll_start() {
    for (int pass = 0; pass < 10000; ++pass) {
      const uint32_t n = rd(kAnalog + 0x10);
      if (!(n & (1u << 13))) {
        wr(kAnalog + 0x14, 1u << 13);
      } else if (!(n & (1u << 12))) {
        wr(kAnalog + 0x14, 1u << 12);
      } else if (!(n & (1u << 31))) {
        spin();
      } else if (n & (1u << 16)) {
        wr(kAnalog + 0x18, 1u << 16);
      } else if (!(n & (1u << 6))) {
        wr(kAnalog + 0x14, 1u << 6);
      } else {
        return;
      }
    }
    ADD_FAILURE() << "usb_pll_start never finished";
  }
  void set_arm_clock_600mhz() {
    uint32_t cbcdr = rd(kCcm + 0x14), cbcmr = rd(kCcm + 0x18), dcdc = rd(kDcdc + 0x0C);
    wr(kCcm + 0x80, rd(kCcm + 0x80) | (3u << 6));
    dcdc = (dcdc & ~0x1Fu) | 18u;
    wr(kDcdc + 0x0C, dcdc);
    while (!(rd(kDcdc) & (1u << 31))) spin();
    cbcdr = (cbcdr & ~(7u << 27)) | (3u << 27);
    wr(kCcm + 0x14, cbcdr);
    cbcmr &= ~(3u << 12);
    wr(kCcm + 0x18, cbcmr);
    cbcdr |= 1u << 25;
    wr(kCcm + 0x14, cbcdr);
    while (rd(kCcm + 0x48) & (1u << 5)) spin();
    wr(kAnalog, 1u << 12);
    wr(kAnalog, (1u << 13) | 100u);
    while (!(rd(kAnalog) & (1u << 31))) spin();
    wr(kCcm + 0x10, 1);
    cbcdr = (cbcdr & ~(3u << 8)) | (3u << 8);
    wr(kCcm + 0x14, cbcdr);
    wr(kCcm + 0x14, rd(kCcm + 0x14) & ~(1u << 25));
    while (rd(kCcm + 0x48) & (1u << 5)) spin();
  }
  void pit_and_rtc() {
    wr(kCcm + 0x6C, rd(kCcm + 0x6C) | (3u << 12));  // CCGR1 PIT
    wr(kPit, 0);
    for (uint32_t ch = 0; ch < 4; ++ch) wr(kPit + 0x108 + 0x10 * ch, 0);
    if (!(rd(kSnvs + 0x38) & 1u)) {
      wr(kSnvs + 0x54, 1546300800u << 15);
      wr(kSnvs + 0x50, 1546300800u >> 17);
      wr(kSnvs + 0x38, rd(kSnvs + 0x38) | 1u);
    }
    wr(kSnvs + 0x08, rd(kSnvs + 0x08) | 1u | (1u << 16));
  }
  void configure_external_ram();
  void analog_init();
  void pwm_and_tempmon_and_usb();

  testing::FakeChip chip;
  testing::FakeWorld world;
  PeripheralBus bus;
  std::unique_ptr<ClockAndPinBlocks> blocks;
};

void Startup::configure_external_ram() {
  const uint32_t pad_ctl[8] = {0x1B0F9u, 0x110F9u, 0x1B0F9u, 0x100F9u, 0x170F9u, 0x170F9u, 0x170F9u, 0x170F9u};
  for (uint32_t pad = 22; pad <= 29; ++pad) wr(kIomuxc + 0x25C + 4 * (pad - 22), pad_ctl[pad - 22]);
  for (uint32_t pad = 22; pad <= 29; ++pad) wr(kIomuxc + 0x06C + 4 * (pad - 22), 8u | 0x10u);
  for (uint32_t offset : {0x32Cu, 0x330u, 0x334u, 0x338u, 0x33Cu, 0x350u}) wr(kIomuxc + 0x400 + offset, 1);
  wr(kCcm + 0x18, (rd(kCcm + 0x18) & ~((7u << 29) | (3u << 8))) | (5u << 29) | (3u << 8));
  wr(kCcm + 0x84, rd(kCcm + 0x84) | (3u << 2));  // CCGR7 FLEXSPI2
  wr(kFlexspi2, rd(kFlexspi2) | 2u);
  wr(kFlexspi2 + 0x08, (rd(0x402A8000u + 0x08) & ~0xFFu) | 0x20u);  // MCR2 from FlexSPI1's
  wr(kFlexspi2 + 0xB8, (rd(0x402A8000u + 0xB8) & 0xFFFFFFC0u) | 1u);
  wr(kFlexspi2 + 0x18, 0x5AF05AF0u);
  wr(kFlexspi2 + 0x1C, 2u);
  for (uint32_t i = 0; i < 64; ++i) wr(kFlexspi2 + 0x200 + 4 * i, 0);
  wr(kFlexspi2, rd(kFlexspi2) | 1u);
  while (rd(kFlexspi2) & 1u) spin();
  for (uint32_t sequence = 0; sequence < 3; ++sequence) {  // exit QPI, reset enable, reset
    wr(kFlexspi2 + 0xA0, 0);
    wr(kFlexspi2 + 0xA4, sequence << 16);
    wr(kFlexspi2 + 0xB0, 1);
    while (!(rd(kFlexspi2 + 0x14) & 1u)) spin();
    wr(kFlexspi2 + 0x14, 1);
  }
  wr(kFlexspi2 + 0xA4, (3u << 16) | 4u);  // read ID
  wr(kFlexspi2 + 0xB0, 1);
  while (!(rd(kFlexspi2 + 0x14) & 1u)) spin();
  EXPECT_NE(rd(kFlexspi2 + 0x100) & 0xFFFFu, 0x5D0Du);  // no PSRAM
  wr(kFlexspi2 + 0x14, 0x21);
}

void Startup::analog_init() {
  wr(kCcm + 0x6C, rd(kCcm + 0x6C) | (3u << 16) | (3u << 8));
  const uint32_t mode = (1u << 2) | (2u << 8) | (1u << 4) | (1u << 5) | 3u;
  for (uint32_t adc : {kAdc1, kAdc2}) {
    wr(adc + 0x44, mode | (1u << 10));
    wr(adc + 0x48, (1u << 5) | (1u << 7));
    while (rd(adc + 0x48) & (1u << 7)) spin();
  }
}

void Startup::pwm_and_tempmon_and_usb() {
  wr(kCcm + 0x78, rd(kCcm + 0x78) | (0xFFu << 16));               // CCGR4 PWM1..4
  wr(kCcm + 0x80, rd(kCcm + 0x80) | (0x3Fu << 26) | (3u << 16));  // CCGR6 QTIMER1..4
  for (uint32_t tmr : {0x401DC000u, 0x401E0000u, 0x401E4000u}) {
    for (uint32_t ch = 0; ch < 4; ++ch) {
      const uint32_t at = tmr + 0x20 * ch;
      wr(at + 0x0C, 0, 2);
      wr(at + 0x0A, 0, 2);
      wr(at + 0x0E, 0x0007u, 2);
      wr(at + 0x14, (1u << 0) | (1u << 13), 2);
      wr(at + 0x06, 24000, 2);
      wr(at + 0x00, 0, 2);
      wr(at + 0x10, 0, 2);
      wr(at + 0x0C, (1u << 13) | (8u << 9) | (1u << 5) | 6u, 2);
    }
  }
  wr(kAnalog + 0x180, rd(kAnalog + 0x180) & ~1u);  // tempmon_init
  wr(kAnalog + 0x190, 3);
  const uint32_t fuse = rd(0x401F44E0u);
  EXPECT_EQ(fuse, Ocotp::kAna1);
  wr(kAnalog + 0x180, rd(kAnalog + 0x180) | (0x4D0u << 20));
  wr(kAnalog + 0x290, rd(kAnalog + 0x290) | (0x4C8u << 16));
  wr(kAnalog + 0x290, rd(kAnalog + 0x290) | 0x5C0u);
  wr(kAnalog + 0x180, rd(kAnalog + 0x180) | 2u);
  wr(kAnalog + 0x120, (0x0Fu << 8) | (6u << 4) | 1u);  // usb_init: PMU_REG_3P0
  wr(kCcm + 0x80, rd(kCcm + 0x80) | 3u);               // CCGR6 USBOH3
  EXPECT_EQ(rd(0x401F4620u) & 0xFFFFFFu, 0x123456u);   // usb_init_serialnumber: MAC0
}

TEST_F(Startup, EveryAccessOfTeensyduinosStartUpIsAnsweredAndTheClocksEndRight) {
  ASSERT_NE(blocks, nullptr);
  std::vector<uint32_t> cores;
  blocks->ccm.add_rates_listener([&](const ClockRates& rates) { cores.push_back(rates.core_hz); });
  reset_handler();
  EXPECT_EQ(blocks->gpr.itcm_size_bytes(), 512u * 1024u);
  EXPECT_EQ(blocks->gpr.dtcm_size_bytes(), 512u * 1024u);
  EXPECT_TRUE(blocks->gpr.flexram_config_from_gpr());
  usb_pll_start();
  reset_pfd();
  set_arm_clock_600mhz();
  pit_and_rtc();
  configure_external_ram();
  analog_init();
  pwm_and_tempmon_and_usb();
  EXPECT_EQ(blocks->ccm.core_clock_hz(), 600000000u);
  EXPECT_EQ(blocks->ccm.ipg_clock_hz(), 150000000u);
  EXPECT_EQ(blocks->ccm.perclk_hz(), 24000000u);
  ASSERT_FALSE(cores.empty());
  EXPECT_EQ(cores.front(), 12000000u);  // the reset clock, reported when the listener was added
  EXPECT_EQ(cores.back(), 600000000u);
  // The only pin changes: the memory pads' pulls, set while their mux still selects GPIO (pins
  // 51, 48, 52, 49, 50, 54 = EMC_22, 24, 26..29 get pull-ups; EMC_23 is no pin, EMC_25's keeper
  // leaves pin 53 a plain input). Then the mux moves them to FlexSPI2 and GPIO lets go.
  std::vector<uint8_t> pulled;
  for (const auto& config : world.configs) {
    EXPECT_EQ(config.config, PinConfig::kInputPullup);
    pulled.push_back(config.pin);
  }
  EXPECT_EQ(pulled, (std::vector<uint8_t>{51, 48, 52, 49, 50, 54}));
  EXPECT_TRUE(world.drives.empty());
  // Simulated time spent polling: the USB PLL (16 µs), the ARM PLL (94 µs), two ADC calibrations.
  EXPECT_LT(chip.now_ns(), kMillisecond);
}

TEST_F(Startup, TheBootRomsClocksStartTheCoreAt396MHz) {
  blocks->apply_boot_rom_clocks();
  EXPECT_EQ(blocks->ccm.core_clock_hz(), 396000000u);               // PLL1 792 MHz ÷ ARM_PODF 2
  EXPECT_EQ(blocks->ccm.ipg_clock_hz(), 132000000u);                // ÷ 3: Teensyduino's F_BUS_ACTUAL at start
  EXPECT_TRUE(rd(kAnalog + 0x30) & (1u << 31));                     // PLL_SYS locked
  EXPECT_EQ(rd(kAnalog) & ((1u << 31) | 0x7Fu), (1u << 31) | 66u);  // PLL_ARM locked, DIV_SELECT 66
  // set_arm_clock takes the same path from here (PERIPH_CLK_SEL is 0) and ends at 600 MHz.
  usb_pll_start();
  set_arm_clock_600mhz();
  EXPECT_EQ(blocks->ccm.core_clock_hz(), 600000000u);
}

}  // namespace
}  // namespace stepdance::sim::image::rt1062
