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

// Everything a run leaves: the marks, the handler costs, the instruction count.
std::vector<uint64_t> trace_of(const std::string& name) {
  DeviceFixture f;
  std::vector<uint64_t> trace;
  if (!f.boot_with_device(name)) return trace;
  std::vector<std::unique_ptr<At>> events;
  for (unsigned k = 0; k < 5; ++k) {
    events.push_back(std::make_unique<At>(f.scheduler, 20 * kMicrosecond + k * 3331, [&f, k] {
      f.chip->set_irq_level(4 + k % 3, true);
    }));
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
