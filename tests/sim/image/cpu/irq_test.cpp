// Interrupts on the emulated core: entry at the pending cycle, IPSR, preemption by priority,
// PRIMASK and BASEPRI, the FPU across a handler. Expected cycles come from the fixtures'
// instruction sequences (tests/sim/image/fixtures/irq_*.S, fpu_isr.S), CPI 1, entry and return
// taking no cycles, at the boot clock of 396 MHz (cycles_at(t) = ceil(t · 0.396)).
#include "fixture.hpp"
#include "test_device.hpp"

namespace stepdance::sim::image::testing {
namespace {

struct IrqFixture : Fixture {
  std::unique_ptr<TestDevice> device;
  bool boot_with_device(const std::string& name) {
    return boot(name, [this](ImageChip& target) {
      device = std::make_unique<TestDevice>(target);
      target.bus().add(*device);
    });
  }
  void pend_at(SimTime time_ns, unsigned irq) {
    events.push_back(std::make_unique<At>(scheduler, time_ns, [this, irq] { chip->set_irq_level(irq, true); }));
  }
  void run_until(SimTime time_ns) {
    scheduler.run_until(time_ns);
    ASSERT_TRUE(stops.empty()) << stops[0].what << " at " << stops[0].symbol;
  }
  std::vector<std::unique_ptr<At>> events;
};

TEST(ImageChipIrq, EntersAtThePendingCycleWithIpsrSet) {
  IrqFixture f;
  ASSERT_TRUE(f.boot_with_device("irq_basic"));
  f.pend_at(10 * kMicrosecond, 3);  // the thread idles in `b .`: cycle 10 µs · 396 MHz = 3960
  f.run_until(20 * kMicrosecond);
  ASSERT_EQ(f.device->marks.size(), 1u);
  EXPECT_EQ(f.device->marks[0].value, 16u + 3);  // IPSR = 16 + IRQ number
  EXPECT_EQ(f.device->marks[0].cycle, 3960u + 1);
  EXPECT_EQ(f.chip->handler_cost(19).entries, 1u);
  EXPECT_EQ(f.chip->handler_cost(19).instructions, 5u);
  EXPECT_EQ(f.chip->current_exception(), 0u);  // back in thread mode
}

TEST(ImageChipIrq, AHigherGroupPriorityPreemptsALowerOneWaits) {
  IrqFixture f;
  ASSERT_TRUE(f.boot_with_device("irq_nesting"));
  const uint64_t c1 = 7920;  // IRQ 4 at 20 µs
  f.pend_at(20 * kMicrosecond, 4);
  f.pend_at(20100, 6);  // lower priority than 4: waits
  f.pend_at(20254, 5);  // cycle ceil(20254 · 0.396) = 8021 = c1 + 101: a loop block's start (5 + 2k)
  f.run_until(40 * kMicrosecond);
  const std::vector<uint32_t> order{40, 50, 41, 60};
  EXPECT_EQ(f.device->values(), order);
  EXPECT_EQ(f.device->cycle_of(40), c1 + 1);
  EXPECT_EQ(f.device->cycle_of(50), 8021u + 1);
  EXPECT_EQ(f.device->cycle_of(41), c1 + 204 + 5);         // IRQ 5's 5 instructions inside
  EXPECT_EQ(f.device->cycle_of(60), c1 + 208 + 5 + 1);     // taken as IRQ 4 returns
  EXPECT_EQ(f.chip->handler_cost(20).instructions, 208u);  // nested ones excluded
  EXPECT_EQ(f.chip->handler_cost(21).instructions, 5u);
  EXPECT_EQ(f.chip->handler_cost(22).instructions, 5u);
}

TEST(ImageChipIrq, AMaskedInterruptIsTakenRightAfterTheMaskDrops) {
  IrqFixture f;
  ASSERT_TRUE(f.boot_with_device("irq_masks"));
  f.pend_at(2 * kMicrosecond, 3);  // cycle 792: inside the PRIMASK loop
  f.pend_at(7 * kMicrosecond, 3);  // cycle 2772: inside the BASEPRI loop
  f.pend_at(7 * kMicrosecond, 6);
  f.run_until(20 * kMicrosecond);
  const std::vector<uint32_t> order{1, 2, 30, 3, 4, 60, 5, 30, 6};
  ASSERT_EQ(f.device->values(), order);
  const uint64_t m2 = f.device->cycle_of(2), m4 = f.device->cycle_of(4), m5 = f.device->cycle_of(5);
  const std::vector<uint64_t> irq3 = f.device->cycles_of(30);
  EXPECT_EQ(irq3[0], m2 + 3);  // cpsie at m2 + 1, entry at m2 + 2, its mark one later
  EXPECT_EQ(irq3[1], m5 + 4);  // msr basepri at m5 + 2, entry at m5 + 3
  // IRQ 6 (above BASEPRI) at the first block start at or after cycle 2772; the loop's blocks
  // start at m4 + 4 + 2k (the first holds the mark's store, the ldr, subs and bne).
  const uint64_t pended = 2772;
  const uint64_t first = m4 + 4 + ((pended - (m4 + 4) + 1) / 2) * 2;
  EXPECT_EQ(f.device->cycle_of(60), first + 1);
}

TEST(ImageChipIrq, AnInterruptTheFirmwarePendsIsTakenAtTheNextBlock) {
  IrqFixture f;
  ASSERT_TRUE(f.boot_with_device("irq_software"));
  f.run_until(10 * kMicrosecond);
  const std::vector<TestDevice::Mark> expected{{1, 23}, {2, 26}, {30, 29}, {3, 34}};
  EXPECT_EQ(f.device->marks, expected);
}

TEST(ImageChipIrq, AThreadOnTheProcessStackStacksThereAndReturnsThere) {
  IrqFixture f;
  ASSERT_TRUE(f.boot_with_device("psp_thread"));
  f.pend_at(2 * kMicrosecond, 3);
  f.run_until(20 * kMicrosecond);
  const std::vector<uint32_t> order{0xFFFFFFFD, 10, 2};  // EXC_RETURN: thread, PSP, basic frame
  EXPECT_EQ(f.device->values(), order);
  EXPECT_EQ(f.word("handler_sp"), 0x20080000u);  // MSP untouched by the frame: the top of DTCM
  EXPECT_EQ(f.word("thread_sp_after"), f.address_of("process_stack") + 256);  // PSP back at its top
}

// A regression: unicorn 2.0.1 opened with UC_MODE_MCLASS is a Cortex-M33 whatever model is asked
// for, and every double-precision instruction was then undefined.
TEST(ImageChipIrq, TheFpuDoesDoublePrecision) {
  IrqFixture f;
  ASSERT_TRUE(f.boot_with_device("fpu_double_m7"));
  f.run_until(10 * kMicrosecond);
  const std::vector<uint32_t> values{0x400E0000, 0x40700000};  // 3.75: double's high word, float
  EXPECT_EQ(f.device->values(), values);
}

TEST(ImageChipIrq, TheThreadsFloatsSurviveAHandlerThatUsesTheFpu) {
  IrqFixture f;
  ASSERT_TRUE(f.boot_with_device("fpu_isr"));
  f.pend_at(3 * kMicrosecond, 3);  // inside the thread's loop, after it set S0-S15 and FPSCR
  f.run_until(20 * kMicrosecond);
  const std::vector<uint32_t> order{1, 0xFFFFFFE9, 2};  // EXC_RETURN: thread, MSP, extended frame
  EXPECT_EQ(f.device->values(), order);
}

}  // namespace
}  // namespace stepdance::sim::image::testing
