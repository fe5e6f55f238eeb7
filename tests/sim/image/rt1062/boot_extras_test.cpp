// The quad timers and FlexSPI as Teensyduino 1.59's startup touches them (pwm.c quadtimer_init,
// startup.c configure_external_ram on a Teensy 4.1 without PSRAM).
#include <gtest/gtest.h>

#include "image/rt1062/flexspi.hpp"
#include "image/rt1062/quad_timer.hpp"

namespace stepdance::sim::image::rt1062 {
namespace {

uint32_t rd(Peripheral& block, uint32_t offset, uint8_t bytes = 4) {
  uint32_t value = 0;
  EXPECT_EQ(block.read(offset, bytes, value), Access::kOk) << block.name() << "+" << offset;
  return value;
}

TEST(QuadTimer, HoldsPwmInitsSettingsAndRefusesToShowACountItDoesNotKeep) {
  QuadTimer tmr1(1);
  EXPECT_EQ(tmr1.gate().ccgr, 6);
  EXPECT_EQ(tmr1.gate().field, 13);       // CCGR6 QTIMER1 (RM §14.7.27)
  EXPECT_EQ(rd(tmr1, 0x1E, 2), 0x000Fu);  // ENBL reset (RM §54.9.14)
  for (uint32_t ch = 0; ch < 4; ++ch) {   // quadtimer_init, channel by channel (16-bit writes)
    const uint32_t at = 0x20 * ch;
    EXPECT_EQ(tmr1.write(at + 0x0C, 2, 0), Access::kOk);                       // CTRL = 0
    EXPECT_EQ(tmr1.write(at + 0x0A, 2, 0), Access::kOk);                       // CNTR = 0
    EXPECT_EQ(tmr1.write(at + 0x0E, 2, 0x0007 | (1u << 0)), Access::kOk);      // SCTRL OEN | OPS | VAL | FORCE
    EXPECT_EQ(tmr1.write(at + 0x14, 2, (1u << 0) | (1u << 13)), Access::kOk);  // CSCTRL CL1(1) | ALT_LOAD
    EXPECT_EQ(tmr1.write(at + 0x06, 2, 24000), Access::kOk);                   // LOAD
    EXPECT_EQ(tmr1.write(at + 0x00, 2, 0), Access::kOk);                       // COMP1
    EXPECT_EQ(tmr1.write(at + 0x10, 2, 0), Access::kOk);                       // CMPLD1
    EXPECT_EQ(tmr1.write(at + 0x0C, 2, (1u << 13) | (8u << 9) | (1u << 5) | 6u),
              Access::kOk);  // CM(1) PCS(8) LENGTH OUTMODE(6)
  }
  EXPECT_EQ(rd(tmr1, 0x26, 2), 24000u);  // channel 1 LOAD
  uint32_t value = 0;
  EXPECT_EQ(tmr1.read(0x0A, 2, value), Access::kUnmodelled);      // CNTR of a counting channel
  EXPECT_EQ(tmr1.write(0x0E, 2, 1u << 14), Access::kUnmodelled);  // TCFIE
}

TEST(FlexSpi, Teensy41PsramProbeFindsNoChip) {
  FlexSpi flexspi2(2);
  EXPECT_EQ(flexspi2.gate().ccgr, 7);
  EXPECT_EQ(flexspi2.gate().field, 1);
  // flexspi2_command / flexspi2_psram_id: IPCR0 = address, IPCR1 = sequence | size, IPCMD = TRG.
  ASSERT_EQ(flexspi2.write(0x0A0, 4, 0), Access::kOk);
  ASSERT_EQ(flexspi2.write(0x0A4, 4, (3u << 16) | 4u), Access::kOk);
  ASSERT_EQ(flexspi2.write(0x0B0, 4, 1), Access::kOk);
  EXPECT_EQ(rd(flexspi2, 0x014) & 1u, 1u);            // INTR IPCMDDONE
  EXPECT_NE(rd(flexspi2, 0x100) & 0xFFFFu, 0x5D0Du);  // not the PSRAM's ID: no PSRAM
  ASSERT_EQ(flexspi2.write(0x014, 4, 0x21), Access::kOk);
  EXPECT_EQ(rd(flexspi2, 0x014), 0u);
  ASSERT_EQ(flexspi2.write(0x000, 4, rd(flexspi2, 0) | 1u), Access::kOk);  // SWRESET
  EXPECT_EQ(rd(flexspi2, 0) & 1u, 0u);
  FlexSpi flexspi1(1);
  EXPECT_EQ(flexspi1.write(0x0B0, 4, 1), Access::kUnmodelled);  // flash commands: not modelled
}

}  // namespace
}  // namespace stepdance::sim::image::rt1062
