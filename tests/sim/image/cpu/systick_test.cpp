// SysTick on the core clock: the handler is entered at the cycle the counter reaches zero, and
// the cycle counter read inside it agrees. Expectations come from the fixture's instruction
// indices (tests/sim/image/fixtures/systick.S), CPI 1.
#include "fixture.hpp"

namespace stepdance::sim::image::testing {
namespace {

// SysTick enabled by the instruction at cycle 17 with CVR 0 and RVR 999: it reaches zero at
// cycles 17 + 1000 k. The handler reads CYCCNT with its second instruction (entry cycle + 1), and
// CYCCNT started at cycle 10.
constexpr uint32_t kEnableCycle = 17, kPeriod = 1000, kCyccntStart = 10;

TEST(ImageChipSysTick, EntersTheHandlerAtEachZeroOfTheCounter) {
  Fixture fixture;
  ASSERT_TRUE(fixture.boot("systick"));
  // 3.5 periods at 396 MHz (the boot clock).
  const SimTime end = fixture.chip->time_of_cycle(kEnableCycle + 3 * kPeriod + kPeriod / 2);
  fixture.scheduler.run_until(end);
  ASSERT_TRUE(fixture.stops.empty()) << fixture.stops[0].what;
  EXPECT_EQ(fixture.word("tick_count"), 3u);
  for (unsigned k = 0; k < 3; ++k) {
    EXPECT_EQ(fixture.word("tick_cyccnt", k), kEnableCycle + (k + 1) * kPeriod + 1 - kCyccntStart) << "tick " << k;
  }
  EXPECT_EQ(fixture.word("tick_ipsr"), 15u);  // IPSR in the SysTick handler
  EXPECT_EQ(fixture.chip->handler_cost(15).entries, 3u);
}

}  // namespace
}  // namespace stepdance::sim::image::testing
