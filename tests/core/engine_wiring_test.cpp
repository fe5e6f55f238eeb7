// The engine's start hooks: every block is asked about the frame period first, then about its
// wiring (Block::check_wiring); any refusal leaves the engine stopped.
#include <stdint.h>

#include <string>
#include <vector>

#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/core/engine.hpp"
#include "support/engine_fixture.hpp"

namespace stepdance {
namespace {

using Log = std::vector<std::string>;

class Checked : public Block {
 public:
  Checked(Log& log, const char* name, bool wiring_ok, bool period_ok = true)
      : log_(log), name_(name), wiring_ok_(wiring_ok), period_ok_(period_ok) {}
  Status begin() { return register_in(Stage::kPreChannel); }
  bool accept_frame_period(uint32_t) override {
    log_.push_back(name_ + ".period");
    return period_ok_;
  }
  bool check_wiring() override {
    log_.push_back(name_ + ".wiring");
    return wiring_ok_;
  }

 private:
  Log& log_;
  std::string name_;
  bool wiring_ok_;
  bool period_ok_;
};

class EngineWiringTest : public test_support::EngineFixture {};

TEST_F(EngineWiringTest, WiringIsCheckedAfterEveryBlockAcceptedThePeriod) {
  Log log;
  Checked a(log, "a", true);
  Checked b(log, "b", true);
  ASSERT_EQ(a.begin(), Status::kOk);
  ASSERT_EQ(b.begin(), Status::kOk);
  EXPECT_EQ(dance_start(), Status::kOk);
  EXPECT_EQ(log, (Log{"a.period", "b.period", "a.wiring", "b.wiring"}));
  EXPECT_TRUE(engine().running());
  engine().stop();
}

TEST_F(EngineWiringTest, ABlockThatRefusesItsWiringKeepsTheEngineStopped) {
  Log log;
  Checked a(log, "a", false);
  Checked b(log, "b", true);
  ASSERT_EQ(a.begin(), Status::kOk);
  ASSERT_EQ(b.begin(), Status::kOk);
  EXPECT_NE(dance_start(), Status::kOk);
  EXPECT_FALSE(engine().running());
  EXPECT_EQ(log, (Log{"a.period", "b.period", "a.wiring", "b.wiring"}));  // every refusal is reported
}

TEST_F(EngineWiringTest, ARefusedPeriodIsNotFollowedByAWiringCheck) {
  Log log;
  Checked a(log, "a", true, false);
  ASSERT_EQ(a.begin(), Status::kOk);
  EXPECT_NE(dance_start(), Status::kOk);
  EXPECT_EQ(log, (Log{"a.period"}));
}

TEST_F(EngineWiringTest, ABlockWithoutTheHookAcceptsAnyWiringAndStepsNothing) {
  class Plain : public Block {
  } plain;
  BlockPort port;
  double world_units = 7.0;
  EXPECT_TRUE(plain.check_wiring());
  EXPECT_FALSE(plain.world_units_per_step(port, world_units));
  EXPECT_EQ(world_units, 7.0);
}

}  // namespace
}  // namespace stepdance
