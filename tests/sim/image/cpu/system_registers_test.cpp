// The core's own registers driven directly (no CPU): reset values and bit layouts from the
// ARMv7-M Architecture Reference Manual (DDI 0403E) and the Cortex-M7 TRM, SysTick timing from
// its counting rules (B3.3), the RT1062's 160 IRQs and 4 priority bits.
#include <gtest/gtest.h>

#include "image/cpu/image_chip.hpp"
#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim::image {
namespace {

struct Core {
  Scheduler scheduler;
  ImageChip chip{scheduler, TeensyModel::kTeensy40};
  uint32_t read(uint32_t address, uint8_t bytes = 4) {
    uint32_t value = 0;
    BusRefusal refusal;
    EXPECT_TRUE(chip.system_bus().read(address, bytes, value, refusal)) << refusal.describe();
    return value;
  }
  void write(uint32_t address, uint32_t value, uint8_t bytes = 4) {
    BusRefusal refusal;
    EXPECT_TRUE(chip.system_bus().write(address, bytes, value, refusal)) << refusal.describe();
  }
};

TEST(ImageCoreRegisters, ScbResetValuesAndKeys) {
  Core core;
  EXPECT_EQ(core.read(0xE000ED00), 0x411FC271u);    // CPUID: Arm, r1p1, Cortex-M7 (0xC27)
  EXPECT_EQ(core.read(0xE000ED14), 0x00040200u);    // CCR: BP, STKALIGN (M7 TRM)
  EXPECT_EQ(core.read(0xE000ED0C) >> 16, 0xFA05u);  // AIRCR reads VECTKEYSTAT
  core.write(0xE000ED0C, 0x00000500);               // no key: ignored
  EXPECT_EQ((core.read(0xE000ED0C) >> 8) & 7, 0u);
  core.write(0xE000ED0C, 0x05FA0500);  // PRIGROUP 5
  EXPECT_EQ((core.read(0xE000ED0C) >> 8) & 7, 5u);
  core.write(0xE000ED08, 0x20001234);  // VTOR: TBLOFF is bits [31:7]
  EXPECT_EQ(core.read(0xE000ED08), 0x20001200u);
  core.write(0xE000ED20, 0x20200000);  // SHPR3: SysTick and PendSV priority 32
  EXPECT_EQ(core.chip.exceptions().priority(15), 0x20);
  EXPECT_EQ(core.chip.exceptions().priority(14), 0x20);
}

TEST(ImageCoreRegisters, NvicHas160LinesAndFourPriorityBits) {
  Core core;
  EXPECT_EQ(core.read(0xE000E004), 4u);        // ICTR.INTLINESNUM: (4 + 1) · 32 = 160
  core.write(0xE000E100 + 4 * 4, 0xFFFFFFFF);  // ISER4: IRQs 128..159
  EXPECT_EQ(core.read(0xE000E100 + 4 * 4), 0xFFFFFFFFu);
  core.write(0xE000E100 + 5 * 4, 0xFFFFFFFF);  // ISER5: no lines there
  EXPECT_EQ(core.read(0xE000E100 + 5 * 4), 0u);
  core.write(0xE000E180 + 4 * 4, 0x00000001);  // ICER4: IRQ 128 off
  EXPECT_EQ(core.read(0xE000E100 + 4 * 4), 0xFFFFFFFEu);
  core.write(0xE000E400 + 7, 0xFF, 1);  // IPR byte of IRQ 7: low 4 bits read zero
  EXPECT_EQ(core.read(0xE000E400 + 4), 0xF0000000u);
  core.write(0xE000E200, 0x4);  // ISPR0: IRQ 2 pending
  EXPECT_TRUE(core.chip.exceptions().pending(18));
  EXPECT_EQ(core.read(0xE000E280), 0x4u);  // ICPR reads the pending bits too
}

TEST(ImageCoreRegisters, SysTickOnTheExternalReferenceReachesZeroEveryHundredTicks) {
  Core core;
  core.write(0xE000E014, 99);                    // RVR: 100 ticks of 10 µs = 1 ms
  core.write(0xE000E018, 0);                     // CVR cleared at t = 0 (tick 0)
  core.write(0xE000E010, 3);                     // ENABLE | TICKINT, CLKSOURCE 0: the 100 kHz reference
  core.scheduler.run_until(500 * kMicrosecond);  // tick 50: reloaded at tick 1 to 99, then 49 down
  EXPECT_EQ(core.read(0xE000E018), 50u);
  EXPECT_FALSE(core.chip.exceptions().pending(15));
  EXPECT_EQ(core.read(0xE000E010) & (1u << 16), 0u);  // COUNTFLAG not yet
  core.scheduler.run_until(1 * kMillisecond - 1);
  EXPECT_FALSE(core.chip.exceptions().pending(15));
  core.scheduler.run_until(1 * kMillisecond);  // tick 100: zero
  EXPECT_TRUE(core.chip.exceptions().pending(15));
  EXPECT_EQ(core.read(0xE000E010) & (1u << 16), 1u << 16);  // COUNTFLAG, cleared by the read
  EXPECT_EQ(core.read(0xE000E010) & (1u << 16), 0u);
  core.scheduler.run_until(1 * kMillisecond + 10 * kMicrosecond);  // tick 101: reloaded
  EXPECT_EQ(core.read(0xE000E018), 99u);
}

TEST(ImageCoreRegisters, DwtCountsOnlyWithTrcenaAndCyccntena) {
  Core core;
  core.write(0xE0001000, 1);  // CYCCNTENA without TRCENA: no count
  EXPECT_EQ(core.read(0xE0001004), 0u);
  core.write(0xE000EDFC, 1u << 24);  // DEMCR.TRCENA
  core.write(0xE0001004, 1234);
  EXPECT_EQ(core.read(0xE0001004), 1234u);     // no instruction has run
  EXPECT_EQ(core.read(0xE0001000) >> 28, 4u);  // NUMCOMP
}

TEST(ImageCoreRegisters, AnUnlistedSystemRegisterIsRefusedWithItsBlock) {
  Core core;
  uint32_t value = 0;
  BusRefusal refusal;
  EXPECT_FALSE(core.chip.system_bus().read(0xE000E01C, 4, value, refusal));  // SYST_CALIB
  EXPECT_NE(refusal.describe().find("SysTick+0xC"), std::string::npos) << refusal.describe();
  EXPECT_FALSE(core.chip.system_bus().read(0xE0000000, 4, value, refusal));  // ITM
  EXPECT_EQ(refusal.kind, BusRefusal::Kind::kNoBlock);
}

}  // namespace
}  // namespace stepdance::sim::image
