// ImageChip::call_function: a debugger's call into a running image (tests/sim/image/fixtures/
// debug_call.c) hands back what the function passes to its callout, changes nothing the image
// or the simulation can see, and reports a function that goes wrong without stopping the image.
#include "fixture.hpp"

namespace stepdance::sim::image::testing {
namespace {

struct Called {
  std::string block;
  uint32_t instance = 0;
  std::string name;
  uint64_t value = 0;
};

std::string string_at(ImageChip& chip, uint32_t address) {
  std::string text;
  char c = 0;
  while (chip.read_memory(address + static_cast<uint32_t>(text.size()), &c, 1) && c != '\0') text += c;
  return text;
}

class DebugCall : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(fixture.boot("debug_call"));
    fixture.run_to(100 * kMicrosecond);
    ASSERT_TRUE(fixture.stops.empty());
  }
  bool call(const std::string& function, const std::array<uint32_t, 4>& args) {
    error.clear();
    return fixture.chip->call_function(
        fixture.address_of(function), args, [this] { on_callout(); }, error);
  }
  void on_callout() {
    ImageChip& chip = *fixture.chip;
    Called call;
    call.block = string_at(chip, chip.read_register(UC_ARM_REG_R1));
    call.instance = chip.read_register(UC_ARM_REG_R2);
    call.name = string_at(chip, chip.read_register(UC_ARM_REG_R3));
    chip.read_memory(chip.read_register(UC_ARM_REG_SP), &call.value, 8);
    called.push_back(call);
  }
  Fixture fixture;
  std::string error;
  std::vector<Called> called;
};

TEST_F(DebugCall, HandsOverEachCalloutsArgumentsAsTheAbiPassesThem) {
  ASSERT_TRUE(call("report", {ImageChip::kCalloutAddress | 1u, 0, 0, 0})) << error;
  ASSERT_EQ(called.size(), 2u);
  EXPECT_EQ(called[0].block, "Alpha");
  EXPECT_EQ(called[0].instance, 1u);
  EXPECT_EQ(called[0].name, "beta");
  EXPECT_EQ(called[0].value, 0x123456789ull);
  EXPECT_EQ(called[1].block, "Gamma");
  EXPECT_EQ(called[1].instance, 2u);
  EXPECT_EQ(called[1].name, "delta");
  EXPECT_EQ(called[1].value, 42u);
}

TEST_F(DebugCall, PassesFourArgumentsInR0ToR3) {
  ASSERT_TRUE(call("add", {1000, 200, 30, 4})) << error;
  EXPECT_EQ(fixture.word("sum"), 1234u);
}

TEST_F(DebugCall, LeavesRegistersTimeAndCountsAsTheyWere) {
  ImageChip& chip = *fixture.chip;
  const int registers[] = {UC_ARM_REG_R0, UC_ARM_REG_R1, UC_ARM_REG_R2, UC_ARM_REG_R3,  UC_ARM_REG_R12,
                           UC_ARM_REG_SP, UC_ARM_REG_LR, UC_ARM_REG_PC, UC_ARM_REG_XPSR};
  std::vector<uint32_t> before;
  for (int reg : registers) before.push_back(chip.read_register(reg));
  const uint64_t instructions = chip.instructions();
  const SimTime now = fixture.scheduler.now();
  const uint32_t spins = fixture.word("spins");
  ASSERT_TRUE(call("report", {ImageChip::kCalloutAddress | 1u, 0, 0, 0})) << error;
  for (size_t i = 0; i < before.size(); ++i) EXPECT_EQ(chip.read_register(registers[i]), before[i]) << "register " << i;
  EXPECT_EQ(chip.instructions(), instructions);
  EXPECT_EQ(fixture.scheduler.now(), now);
  EXPECT_EQ(fixture.word("spins"), spins);
  fixture.run_to(200 * kMicrosecond);  // the image runs on from where it was
  EXPECT_TRUE(fixture.stops.empty());
  EXPECT_GT(fixture.word("spins"), spins);
}

TEST_F(DebugCall, AFunctionThatGoesWrongIsReportedAndTheImageRunsOn) {
  EXPECT_FALSE(call("touch_register", {0, 0, 0, 0}));
  EXPECT_NE(error.find("register at 0x401F8000"), std::string::npos) << error;
  EXPECT_FALSE(call("jump_nowhere", {0, 0, 0, 0}));
  EXPECT_NE(error.find("0x90000000"), std::string::npos) << error;
  EXPECT_FALSE(call("never_return", {0, 0, 0, 0}));
  EXPECT_NE(error.find("instruction budget"), std::string::npos) << error;
  const uint32_t spins = fixture.word("spins");
  fixture.run_to(200 * kMicrosecond);
  EXPECT_TRUE(fixture.stops.empty());
  EXPECT_GT(fixture.word("spins"), spins);
}

}  // namespace
}  // namespace stepdance::sim::image::testing
