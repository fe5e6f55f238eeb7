// Time inside a block: a register access happens at its own instruction's cycle, DWT CYCCNT is
// the instruction count, the core clock sets the time, and reruns are identical.
#include "fixture.hpp"
#include "test_device.hpp"

namespace stepdance::sim::image::testing {
namespace {

struct DeviceFixture : Fixture {
  std::unique_ptr<TestDevice> device;
  bool boot_with_device(const std::string& name) {
    return boot(name, [this](ImageChip& target) {
      device = std::make_unique<TestDevice>(target);
      target.bus().add(*device);
    });
  }
};

// Cycles from tests/sim/image/fixtures/access_timing.S's instruction indices.
TEST(ImageChipTiming, ARegisterAccessIsTimedAtItsOwnInstruction) {
  DeviceFixture f;
  ASSERT_TRUE(f.boot_with_device("access_timing"));
  f.scheduler.run_until(10 * kMicrosecond);
  ASSERT_TRUE(f.stops.empty()) << f.stops[0].what << " at " << f.stops[0].symbol;
  const std::vector<TestDevice::Mark> expected{{1, 21}, {0x5A, 24}, {12, 27}, {2, 30}};
  EXPECT_EQ(f.device->marks, expected);
}

TEST(ImageChipTiming, TheCycleCounterIsTheInstructionCount) {
  DeviceFixture f;
  ASSERT_TRUE(f.boot_with_device("access_timing"));
  f.run_to(10 * kMicrosecond);
  ASSERT_EQ(f.device->marks.size(), 4u);
  EXPECT_EQ(f.device->marks[2].value, 26u - 14u);  // read at cycle 26, counting from cycle 14
  // The idle loop retires one instruction per cycle to the end: 10 µs at 396 MHz.
  EXPECT_EQ(f.chip->instructions(), 3960u);
}

// stop_cpu_run() ends the run after the access's block; the core then resumes where it was.
TEST(ImageChipTiming, StopCpuRunEndsTheRunAndTheCoreResumes) {
  uint64_t handled[2], instructions[2];
  for (int stop = 0; stop < 2; ++stop) {
    DeviceFixture f;
    ASSERT_TRUE(f.boot_with_device("access_timing"));
    f.device->stop_on_write = stop == 1;
    f.run_to(10 * kMicrosecond);
    handled[stop] = f.scheduler.handled();
    instructions[stop] = f.chip->instructions();
  }
  EXPECT_EQ(handled[1], handled[0] + 1);  // one more firing of the CPU's event
  EXPECT_EQ(instructions[1], instructions[0]);
  EXPECT_EQ(instructions[0], 3960u);
}

TEST(ImageChipTiming, TimeFollowsTheCoreClock) {
  DeviceFixture f;
  ASSERT_TRUE(f.boot_with_device("access_timing"));
  f.run_to(1 * kMicrosecond);  // 396 cycles at the boot clock
  EXPECT_EQ(f.chip->instructions(), 396u);
  f.chip->set_core_clock_hz(600000000);
  f.run_to(2 * kMicrosecond);  // one more µs at 600 MHz
  EXPECT_EQ(f.chip->instructions(), 396u + 600u);
  EXPECT_EQ(f.chip->time_of_cycle(f.chip->instructions()), 2 * kMicrosecond);
}

TEST(ImageChipTiming, ReachingAnAddressReportsTheInstructionsBeforeIt) {
  DeviceFixture f;
  std::vector<std::pair<uint64_t, SimTime>> reached;
  ASSERT_TRUE(f.boot_with_device("irq_basic"));
  f.chip->on_reach(f.address_of("irq3_handler"),
                   [&reached](uint64_t instructions, SimTime time) { reached.emplace_back(instructions, time); });
  At pend(f.scheduler, 10 * kMicrosecond, [&f] { f.chip->set_irq_level(3, true); });
  f.run_to(20 * kMicrosecond);
  ASSERT_EQ(reached.size(), 1u);
  EXPECT_EQ(reached[0].first, 3960u);  // entered at 10 µs: 3960 cycles at 396 MHz, all instructions
  EXPECT_EQ(reached[0].second, 10 * kMicrosecond);
}

// tests/sim/image/fixtures/sleep.S: WFI and WFE sleep to the next SysTick; YIELD runs on.
TEST(ImageChipTiming, WfiAndWfeSleepUntilAnInterrupt) {
  Fixture f;
  ASSERT_TRUE(f.boot("sleep"));
  f.run_to(10 * kMillisecond + 5 * kMicrosecond);
  ASSERT_TRUE(f.stops.empty()) << f.stops[0].what << " at " << f.stops[0].symbol;
  EXPECT_EQ(f.word("ticks"), 10u);
  // Each SysTick wakes the WFI (then the loop runs to the WFE) or the WFE (then it loops to the
  // WFI): two ticks per turn of the loop.
  EXPECT_EQ(f.word("wakes"), 5u);
  // Instructions: the 25-instruction start, yield and wfi; then per two ticks two handlers of 5,
  // ldr, adds, str, wfe after the first and b, yield, wfi after the second — asleep in between.
  EXPECT_EQ(f.chip->instructions(), 25u + 2 + 5 * (10 + 4 + 3));
  EXPECT_EQ(f.chip->handler_cost(15).entries, 10u);
}

// Everything a run leaves: the marks, the handler costs, the instruction count.
std::vector<uint64_t> trace_of(const std::string& name) {
  DeviceFixture f;
  std::vector<uint64_t> trace;
  if (!f.boot_with_device(name)) return trace;
  std::vector<std::unique_ptr<At>> events;
  for (unsigned k = 0; k < 5; ++k) {
    events.push_back(std::make_unique<At>(f.scheduler, 20 * kMicrosecond + k * 3331,
                                          [&f, k] { f.chip->set_irq_level(4 + k % 3, true); }));
  }
  f.scheduler.run_until(100 * kMicrosecond);
  for (const TestDevice::Mark& mark : f.device->marks) {
    trace.push_back(mark.value);
    trace.push_back(mark.cycle);
  }
  for (unsigned n = 0; n < kExceptionCount; ++n) {
    trace.push_back(f.chip->handler_cost(n).entries);
    trace.push_back(f.chip->handler_cost(n).instructions);
  }
  trace.push_back(f.chip->instructions());
  return trace;
}

TEST(ImageChipTiming, TwoRunsGiveIdenticalTraces) {
  const std::vector<uint64_t> first = trace_of("irq_nesting");
  ASSERT_GT(first.size(), 2 * kExceptionCount + 1 + 8);  // some marks were made
  EXPECT_EQ(trace_of("irq_nesting"), first);
}

}  // namespace
}  // namespace stepdance::sim::image::testing
