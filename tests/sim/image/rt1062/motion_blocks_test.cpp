// add_motion_blocks: every block on the bus at the reference manual's address, or none at all.
#include "image/rt1062/motion_blocks.hpp"

#include <gtest/gtest.h>

#include <string>

#include "motion_fakes.hpp"

namespace stepdance::sim::image {
namespace {

using testing::FakeClockBlock;
using testing::Rig;

TEST(MotionBlocks, PutsEveryBlockAtItsAddress) {
  Rig rig;
  auto blocks = add_motion_blocks(rig.bus, rig.chip, rig.io, TeensyModel::kTeensy41);
  ASSERT_NE(blocks, nullptr);
  // RM §2.3 memory map (and Teensyduino's imxrt.h IMXRT_*_ADDRESS).
  const std::pair<uint32_t, const char*> expected[] = {
      {0x42020000u, "FLEXIO3"}, {0x403DC000u, "PWM1"},   {0x403E0000u, "PWM2"}, {0x403E4000u, "PWM3"},
      {0x403E8000u, "PWM4"},    {0x403BC000u, "XBARA1"}, {0x403C8000u, "ENC1"}, {0x403CC000u, "ENC2"},
      {0x403F0000u, "LPI2C1"},  {0x403F8000u, "LPI2C3"},
  };
  for (const auto& [address, name] : expected) {
    const Peripheral* block = rig.bus.find(address);
    ASSERT_NE(block, nullptr) << name;
    EXPECT_EQ(std::string(block->name()), name);
  }
  EXPECT_EQ(rig.bus.blocks().size(), 2u + 10u);  // the rig's CCM and CCM_ANALOG, and these
}

TEST(MotionBlocks, AnOverlapAddsNothing) {
  Rig rig;
  FakeClockBlock squatter{"SQUATTER", 0x403F8000u};  // where LPI2C3 goes
  rig.bus.add(squatter);
  EXPECT_EQ(add_motion_blocks(rig.bus, rig.chip, rig.io, TeensyModel::kTeensy41), nullptr);
  EXPECT_EQ(rig.bus.blocks().size(), 3u) << "no block of the group was added";
  EXPECT_EQ(rig.bus.find(0x42020000u), nullptr);
}

TEST(MotionBlocks, InputPortDirPinsComeFromTheBoardTable) {
  // Driver Module v1.0: input ports A–D are STEP/DIR 4/6, 5/7, 8/10, 9/11.
  EXPECT_EQ(InputCapture::dir_pin(0), 6u);
  EXPECT_EQ(InputCapture::dir_pin(3), 11u);
  EXPECT_EQ(InputCapture::dir_pin(4), 255u);
}

}  // namespace
}  // namespace stepdance::sim::image
