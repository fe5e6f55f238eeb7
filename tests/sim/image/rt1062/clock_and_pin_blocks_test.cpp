// The registration call: every block reachable at its manual address, the CCM answering gates.
#include "image/rt1062/clock_and_pin_blocks.hpp"

#include <gtest/gtest.h>

#include "fake_chip.hpp"

namespace stepdance::sim::image::rt1062 {
namespace {

TEST(ClockAndPinBlocks, AddsEveryBlockAtItsAddressAndWiresTheGates) {
  testing::FakeChip chip;
  testing::FakeWorld world;
  PeripheralBus bus;
  auto blocks = add_clock_and_pin_blocks(bus, chip, world, TeensyModel::kTeensy41);
  ASSERT_NE(blocks, nullptr);
  // RM table 2-2 addresses.
  const std::pair<uint32_t, const char*> expected[] = {
      {0x400FC000u, "CCM"},        {0x400D8000u, "CCM_ANALOG"}, {0x40080000u, "DCDC"},     {0x401F8000u, "IOMUXC"},
      {0x400AC000u, "IOMUXC_GPR"}, {0x401B8000u, "GPIO1"},      {0x400C0000u, "GPIO5"},    {0x42000000u, "GPIO6"},
      {0x4200C000u, "GPIO9"},      {0x401EC000u, "GPT1"},       {0x401F0000u, "GPT2"},     {0x40084000u, "PIT"},
      {0x400C4000u, "ADC1"},       {0x400C8000u, "ADC2"},       {0x401F4000u, "OCOTP"},    {0x400D4000u, "SNVS"},
      {0x401DC000u, "TMR1"},       {0x401E8000u, "TMR4"},       {0x402A4000u, "FLEXSPI2"}, {0x402A8000u, "FLEXSPI"}};
  for (const auto& [address, name] : expected) {
    ASSERT_NE(bus.find(address), nullptr) << name;
    EXPECT_STREQ(bus.find(address)->name(), name);
  }
  BusRefusal refusal;
  uint32_t ccgr1 = 0;
  ASSERT_TRUE(bus.read(0x400FC06Cu, 4, ccgr1, refusal));
  ASSERT_TRUE(bus.write(0x400FC06Cu, 4, ccgr1 & ~(3u << 26), refusal));  // GPIO1 gate (CG13) off
  uint32_t value = 0;
  EXPECT_FALSE(bus.read(0x401B8000u, 4, value, refusal));
  EXPECT_EQ(refusal.kind, BusRefusal::Kind::kGateOff);
}

TEST(ClockAndPinBlocks, RefusesToOverlapAndLeavesTheBusAsItWas) {
  testing::FakeChip chip;
  testing::FakeWorld world;
  PeripheralBus bus;
  Dcdc squatter;  // already at 0x40080000
  ASSERT_TRUE(bus.add(squatter));
  EXPECT_EQ(add_clock_and_pin_blocks(bus, chip, world, TeensyModel::kTeensy40), nullptr);
  EXPECT_EQ(bus.blocks().size(), 1u);
}

}  // namespace
}  // namespace stepdance::sim::image::rt1062
