// GPIO1..9 through the pads to a fake world, driven as our backend (pins.cpp, gpio.cpp) and
// Teensyduino (digital.c, interrupt.c) drive them.
#include "image/rt1062/gpio_pads.hpp"

#include <gtest/gtest.h>

#include "fake_chip.hpp"
#include "image/chip/peripheral_bus.hpp"

namespace stepdance::sim::image::rt1062 {
namespace {

// Addresses: RM table 2-2, §11.7 (pad registers), §11.4 (GPR26..29), §12.5 (GPIO registers).
constexpr uint32_t kIomuxc = 0x401F8000u, kGpr = 0x400AC000u;
constexpr uint32_t kGpio1 = 0x401B8000u, kGpio7 = 0x42004000u, kGpio9 = 0x4200C000u;
constexpr uint32_t kDr = 0x00, kGdir = 0x04, kPsr = 0x08, kIcr1 = 0x0C, kImr = 0x14, kIsr = 0x18, kDrSet = 0x84,
                   kDrClear = 0x88, kDrToggle = 0x8C;
// Pin 13 = GPIO_B0_03 (mux 0x148, pad 0x338), GPIO2/7 bit 3; pin 2 = GPIO_EMC_04 (mux 0x024),
// GPIO4/9 bit 4; pin 0 = GPIO_AD_B0_03 (mux 0x0C8), GPIO1/6 bit 3. (core_pins.h; RM §11.7.)
constexpr uint32_t kMuxB0_03 = 0x148, kPadB0_03 = 0x338, kMuxEmc04 = 0x024, kPadEmc04 = 0x214;

class GpioChip : public ::testing::Test {
 protected:
  GpioChip() : pads(chip, world, TeensyModel::kTeensy41, iomuxc, gpr) {
    EXPECT_TRUE(bus.add(iomuxc));
    EXPECT_TRUE(bus.add(gpr));
    for (unsigned n = 1; n <= 9; ++n) EXPECT_TRUE(bus.add(pads.port(n)));
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

  testing::FakeChip chip;
  testing::FakeWorld world;
  Iomuxc iomuxc;
  IomuxcGpr gpr;
  GpioPads pads;
  PeripheralBus bus;
};

TEST_F(GpioChip, PadRegistersResetToGpioWithTheKeeper) {
  EXPECT_EQ(rd(kIomuxc + kMuxB0_03), 5u);       // ALT5 = GPIO2_IO03 (RM §11.7)
  EXPECT_EQ(rd(kIomuxc + kPadB0_03), 0x10B0u);  // RM §11.7 reset value
  EXPECT_EQ(rd(kGpr + 0x6C), 0u);               // GPR27: GPIO2 drives the B0/B1 pads
  wr(kIomuxc + kMuxB0_03, 0xFFFFFFFFu);
  EXPECT_EQ(rd(kIomuxc + kMuxB0_03), 0x1Fu);  // MUX_MODE and SION only; the rest reads 0
  uint32_t value = 0;
  BusRefusal refusal;
  EXPECT_FALSE(bus.read(kIomuxc + 0x790, 4, value, refusal));  // past the last daisy select
  EXPECT_EQ(refusal.kind, BusRefusal::Kind::kUnmodelled);
}

TEST_F(GpioChip, AnOutputWriteReachesTheWorldAtTheAccessTime) {
  chip.advance_to(1000);
  // Our backend's gpio_mode(13, kOutput): pad control, GPR27 fast select, GDIR, then mux + SION.
  wr(kIomuxc + kPadB0_03, (6u << 3) | (1u << 6));
  wr(kGpr + 0x6C, rd(kGpr + 0x6C) | (1u << 3));
  wr(kGpio7 + kGdir, rd(kGpio7 + kGdir) | (1u << 3));
  wr(kIomuxc + kMuxB0_03, 5u | (1u << 4));
  ASSERT_EQ(world.configs.size(), 1u);
  EXPECT_EQ(world.configs[0].pin, 13);
  EXPECT_EQ(world.configs[0].config, PinConfig::kOutput);
  EXPECT_EQ(world.configs[0].time, 1000);
  ASSERT_EQ(world.drives.size(), 1u);
  EXPECT_FALSE(world.drives[0].high);
  chip.advance_to(2500);
  wr(kGpio7 + kDrSet, 1u << 3);  // gpio_write(13, true)
  ASSERT_EQ(world.drives.size(), 2u);
  EXPECT_EQ(world.drives[1].time, 2500);
  EXPECT_TRUE(world.drives[1].high);
  EXPECT_GE(chip.stops, 2);
  wr(kGpio7 + kDrSet, 1u << 3);  // no change: the world hears nothing
  EXPECT_EQ(world.drives.size(), 2u);
  chip.advance_to(4000);
  wr(kGpio7 + kDrToggle, 1u << 3);
  EXPECT_FALSE(world.drives.back().high);
  EXPECT_EQ(world.drives.back().time, 4000);
  // The slow twin GPIO2 does not drive the pad while GPR27 selects GPIO7.
  wr(0x401BC000u + kGdir, 1u << 3);
  wr(0x401BC000u + kDr, 1u << 3);
  EXPECT_FALSE(world.drives.back().high);
  EXPECT_EQ(rd(kGpio7 + kDr), 0u);
}

TEST_F(GpioChip, AnInputReadsTheWorldsLevelWithItsPull) {
  // Teensyduino pinMode(2, INPUT_PULLUP): pad = DSE(7) | PKE | PUE | PUS(3) | HYS, GDIR bit clear.
  wr(kGpr + 0x74, 0xFFFFFFFFu);  // startup.c: GPR29 = all fast
  wr(kIomuxc + kPadEmc04, (7u << 3) | (1u << 12) | (1u << 13) | (3u << 14) | (1u << 16));
  ASSERT_EQ(world.configs.size(), 1u);
  EXPECT_EQ(world.configs[0].pin, 2);
  EXPECT_EQ(world.configs[0].config, PinConfig::kInputPullup);
  world.levels[2] = true;
  EXPECT_EQ(rd(kGpio9 + kPsr) & (1u << 4), 1u << 4);
  EXPECT_EQ(rd(kGpio9 + kDr) & (1u << 4), 1u << 4);  // DR of an input reads the pad
  world.levels[2] = false;
  EXPECT_EQ(rd(kGpio9 + kPsr) & (1u << 4), 0u);
  // Muxed away from GPIO without SION, the GPIO no longer sees the pad.
  world.levels[2] = true;
  wr(kIomuxc + kMuxEmc04, 1u);
  EXPECT_EQ(rd(kGpio9 + kPsr) & (1u << 4), 0u);
}

TEST_F(GpioChip, ARisingEdgeRaisesTheFastGpioInterruptUntilCleared) {
  wr(kGpr + 0x74, 0xFFFFFFFFu);
  // attachInterrupt(2, isr, RISING): ICR1 field 4 = 10 (rising), ISR cleared, IMR bit set.
  wr(kGpio9 + kIcr1, 2u << 8);
  wr(kGpio9 + kIsr, 1u << 4);
  wr(kGpio9 + kImr, 1u << 4);
  EXPECT_FALSE(chip.irq_levels[157]);
  chip.advance_to(7000);
  world.levels[2] = true;
  pads.world_changed();
  EXPECT_TRUE(chip.irq_levels[157]);  // GPIO6_7_8_9 combined line (RM table 4-2: IRQ 157)
  EXPECT_EQ(chip.irq_log.back().time, 7000);
  // (Other bits latch too: ICR 00 = low level is their reset setting, RM §12.5.4; IMR masks them.)
  EXPECT_EQ(rd(kGpio9 + kIsr) & (1u << 4), 1u << 4);
  wr(kGpio9 + kIsr, 1u << 4);  // the ISR clears the flag: the line falls
  EXPECT_FALSE(chip.irq_levels[157]);
  world.levels[2] = false;  // a falling edge does not flag a rising-edge pin
  pads.world_changed();
  EXPECT_EQ(rd(kGpio9 + kIsr) & (1u << 4), 0u);
  EXPECT_FALSE(chip.irq_levels[157]);
}

TEST_F(GpioChip, ALevelInterruptOnGpio1StaysWhileTheLevelHolds) {
  // GPIO1 (slow) drives the AD_B0 pads while GPR26 is 0: pin 0 = GPIO1 bit 3, high level (01).
  wr(kGpio1 + kIcr1, 1u << 6);
  wr(kGpio1 + kIsr, 0xFFFFFFFFu);
  wr(kGpio1 + kImr, 1u << 3);
  world.levels[0] = true;
  pads.world_changed();
  EXPECT_TRUE(chip.irq_levels[80]);  // GPIO1 combined 0-15
  EXPECT_TRUE(chip.irq_levels[75]);  // GPIO1_INT3
  wr(kGpio1 + kIsr, 1u << 3);        // still high: flagged again at once
  EXPECT_TRUE(chip.irq_levels[80]);
  world.levels[0] = false;
  pads.world_changed();
  wr(kGpio1 + kIsr, 1u << 3);
  EXPECT_FALSE(chip.irq_levels[80]);
  EXPECT_FALSE(chip.irq_levels[75]);
}

TEST_F(GpioChip, TheSlowPortsAreGatedTheFastOnesAreNot) {
  EXPECT_EQ(pads.port(1).gate().ccgr, 1);  // GPIO1: CCGR1 CG13 (RM §14.7.22)
  EXPECT_EQ(pads.port(1).gate().field, 13);
  EXPECT_EQ(pads.port(2).gate().ccgr, 0);  // GPIO2: CCGR0 CG15 (RM §14.7.21)
  EXPECT_EQ(pads.port(2).gate().field, 15);
  EXPECT_LT(pads.port(7).gate().ccgr, 0);
  EXPECT_EQ(pads.port(7).base(), kGpio7);
  EXPECT_STREQ(pads.port(9).name(), "GPIO9");
}

}  // namespace
}  // namespace stepdance::sim::image::rt1062
