// The peripheral bus: address → block, clock gates, and refusals that name what was refused.
#include "image/chip/peripheral_bus.hpp"

#include <gtest/gtest.h>

namespace stepdance::sim::image {
namespace {

// A block with one register at offset 4; every other offset is unmodelled.
class OneRegister : public Peripheral {
 public:
  OneRegister(const char* name, uint32_t base, ClockGate gate = {}) : name_(name), base_(base), gate_(gate) {}
  const char* name() const override { return name_; }
  uint32_t base() const override { return base_; }
  uint32_t size_bytes() const override { return 0x4000; }
  ClockGate gate() const override { return gate_; }
  Access read(uint32_t offset, uint8_t, uint32_t& value) override {
    if (offset != 4) return Access::kUnmodelled;
    value = register_;
    return Access::kOk;
  }
  Access write(uint32_t offset, uint8_t, uint32_t value) override {
    if (offset != 4) return Access::kUnmodelled;
    register_ = value;
    return Access::kOk;
  }

 private:
  const char* name_;
  uint32_t base_;
  ClockGate gate_;
  uint32_t register_ = 0;
};

TEST(PeripheralBus, RoutesEachAddressToTheBlockCoveringIt) {
  OneRegister gpio1("GPIO1", 0x401B8000), gpio2("GPIO2", 0x401BC000);
  PeripheralBus bus;
  ASSERT_TRUE(bus.add(gpio2));
  ASSERT_TRUE(bus.add(gpio1));
  BusRefusal refusal;
  ASSERT_TRUE(bus.write(0x401BC004, 4, 0x1234, refusal));
  uint32_t value = 0;
  ASSERT_TRUE(bus.read(0x401BC004, 4, value, refusal));
  EXPECT_EQ(value, 0x1234u);
  ASSERT_TRUE(bus.read(0x401B8004, 4, value, refusal));
  EXPECT_EQ(value, 0u);
  EXPECT_EQ(bus.find(0x401BFFFF), &gpio2);
  EXPECT_EQ(bus.find(0x401C0000), nullptr);
}

TEST(PeripheralBus, RefusesOverlappingBlocks) {
  OneRegister a("A", 0x40000000), b("B", 0x40002000);
  PeripheralBus bus;
  ASSERT_TRUE(bus.add(a));
  EXPECT_FALSE(bus.add(b));
  EXPECT_EQ(bus.blocks().size(), 1u);
}

TEST(PeripheralBus, NamesTheAddressOfAnUnmodelledRegister) {
  OneRegister gpr("IOMUXC_GPR", 0x400AC000);
  PeripheralBus bus;
  ASSERT_TRUE(bus.add(gpr));
  BusRefusal refusal;
  uint32_t value = 0xDEADBEEF;
  EXPECT_FALSE(bus.read(0x400AC044, 4, value, refusal));
  EXPECT_EQ(refusal.kind, BusRefusal::Kind::kUnmodelled);
  EXPECT_EQ(refusal.describe(), "read of 4 bytes at 0x400AC044 (IOMUXC_GPR+0x44): this register is not modelled");
  EXPECT_FALSE(bus.write(0x50000000, 1, 0, refusal));
  EXPECT_EQ(refusal.kind, BusRefusal::Kind::kNoBlock);
  EXPECT_EQ(refusal.describe(), "write of 1 byte at 0x50000000: no peripheral is modelled at this address");
}

TEST(PeripheralBus, AGatedBlockAnswersOnlyWhileItsGateIsOn) {
  OneRegister flexio3("FLEXIO3", 0x42020000, ClockGate{7, 3});
  PeripheralBus bus;
  ASSERT_TRUE(bus.add(flexio3));
  bool on = false;
  bus.set_gate_query([&](ClockGate gate) { return on && gate.ccgr == 7 && gate.field == 3; });
  BusRefusal refusal;
  EXPECT_FALSE(bus.write(0x42020004, 4, 1, refusal));
  EXPECT_EQ(refusal.kind, BusRefusal::Kind::kGateOff);
  EXPECT_NE(refusal.describe().find("CCM_CCGR7 CG3 is off"), std::string::npos);
  on = true;
  EXPECT_TRUE(bus.write(0x42020004, 4, 1, refusal));
}

}  // namespace
}  // namespace stepdance::sim::image
