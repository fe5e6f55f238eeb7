// Double-precision instructions beside runs that end inside chained blocks and exceptions taken
// there with an FP frame (tests/sim/image/fixtures/double_sites.S). While doubles ran in software
// (vfp_hooks.cpp: NOP.W + a code hook), unicorn 2.0.1 left the PC of a run stopped by the block
// hook at an earlier block's start: the run resumed there and pushed twice (Step-A-Sketch's image
// died in micros() at 0.6 ms; UnicornStop shows the emulator's side). The engine is now a real
// Cortex-M7 whose FPU runs doubles itself, so no code hook exists here; the pattern stays tested.
#include "fixture.hpp"
#include "test_device.hpp"

namespace stepdance::sim::image::testing {
namespace {

struct DoubleSitesFixture : Fixture {
  std::unique_ptr<TestDevice> device;
  bool boot_with_device() {
    return boot("double_sites", [this](ImageChip& target) {
      device = std::make_unique<TestDevice>(target);
      device->stop_on_write = true;  // every call of pushpop ends the CPU's run inside it
      target.bus().add(*device);
    });
  }
};

TEST(ImageChipDoubleSites, RunsEndingInChainedBlocksResumeWhereTheyStopped) {
  DoubleSitesFixture f;
  ASSERT_TRUE(f.boot_with_device());
  f.run_to(200 * kMicrosecond);
  ASSERT_TRUE(f.stops.empty()) << f.stops[0].what << " at " << f.stops[0].symbol;
  // 2: SP and r5 kept over 8 calls; 3: and over 200 more with SysTick interrupting, the handler's
  // double count equal to its integer count, d0 = 208.0 (restored from the extended frames).
  ASSERT_EQ(f.device->marks.size(), 2u);
  EXPECT_EQ(f.device->marks[0].value, 2u);
  EXPECT_EQ(f.device->marks[1].value, 3u);
}

TEST(ImageChipDoubleSites, TheHandlerRanOnTheFpFrameAndTheFpuRanTheDoubles) {
  DoubleSitesFixture f;
  ASSERT_TRUE(f.boot_with_device());
  f.run_to(200 * kMicrosecond);
  ASSERT_TRUE(f.stops.empty()) << f.stops[0].what << " at " << f.stops[0].symbol;
  EXPECT_GT(f.word("tick_count"), 10u);  // 200 calls of ~20 cycles at one tick per 150 cycles
  // The Cortex-M7 model's own FPU ran all 8 + 200 + 2 + 2 per tick: no software path taken.
  const ImageChip::DoubleOps ops = f.chip->double_ops();
  EXPECT_EQ(ops.executed, 0u);
  EXPECT_EQ(ops.sites, 0u);
}

}  // namespace
}  // namespace stepdance::sim::image::testing
