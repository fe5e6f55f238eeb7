// Double-precision arithmetic on the emulated core (tests/sim/image/fixtures/fpu_double.S), on
// the Cortex-M7's own FPU (FPv5-D16: image_chip.cpp opens unicorn as a real M7). Expected
// results are the closed forms in the fixture's header; cycles count one per instruction
// (CPI 1) from the fixture's listing.
#include "fixture.hpp"
#include "test_device.hpp"

namespace stepdance::sim::image::testing {
namespace {

struct DoubleFixture : Fixture {
  std::unique_ptr<TestDevice> device;
  std::vector<std::unique_ptr<At>> events;
  bool boot_with_device() {
    return boot("fpu_double", [this](ImageChip& target) {
      device = std::make_unique<TestDevice>(target);
      target.bus().add(*device);
    });
  }
};

TEST(ImageChipDouble, ALoopOfDoubleArithmeticGivesExactResultsAndCountsEachInstructionOnce) {
  DoubleFixture f;
  ASSERT_TRUE(f.boot_with_device());
  f.scheduler.run_until(100 * kMicrosecond);  // 10048 instructions at 396 MHz: 25.4 µs
  ASSERT_TRUE(f.stops.empty()) << f.stops[0].what << " at " << f.stops[0].symbol;
  const std::vector<TestDevice::Mark> expected{{1, 18},    {501, 10033},       {251250, 10036}, {0xFFFFFFFF, 10039},
                                               {3, 10045}, {0x80000000, 10047}};
  EXPECT_EQ(f.device->marks, expected);
}

TEST(ImageChipDouble, AnInterruptThatUsesDoublesLeavesTheThreadsResults) {
  DoubleFixture f;
  ASSERT_TRUE(f.boot_with_device());
  f.events.push_back(std::make_unique<At>(f.scheduler, 10 * kMicrosecond, [&f] { f.chip->set_irq_level(3, true); }));
  f.scheduler.run_until(100 * kMicrosecond);
  ASSERT_TRUE(f.stops.empty()) << f.stops[0].what << " at " << f.stops[0].symbol;
  const std::vector<uint32_t> values{1, 77, 501, 251250, 0xFFFFFFFF, 3, 0x80000000};
  EXPECT_EQ(f.device->values(), values);
  EXPECT_EQ(f.chip->handler_cost(16 + 3).entries, 1u);
}

}  // namespace
}  // namespace stepdance::sim::image::testing
