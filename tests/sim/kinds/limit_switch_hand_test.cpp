// A limit switch held by a hand (timeline press/release/click, the view's button) as well as tripped by the machine.
#include <gtest/gtest.h>

#include "kinds/devices/limit_switch.hpp"
#include "kinds/sim_device.hpp"
#include "scenario/scenario.hpp"

namespace stepdance::sim {
namespace {

/// Keeps the line a device plugs into LIMIT_A; no machine (so only the hand closes the switch).
class LinePlug : public DevicePlug {
 public:
  void connect_encoder(scenario::Connector, Source<int64_t>) override {}
  void connect_analog(scenario::Connector, Source<uint16_t>) override {}
  void connect_digital(scenario::Connector, Source<bool> level) override { line = std::move(level); }
  void attach_i2c(scenario::Connector, uint8_t, I2cDevice*) override {}
  std::function<const Machine*()> machine() const override {
    return [] { return static_cast<const Machine*>(nullptr); };
  }
  uint64_t seed() const override { return 1; }
  Source<bool> line;
};

scenario::Action action(scenario::ActionType type, double time_ms, double hold_ms = 0) {
  scenario::Action made;
  made.type = type;
  made.target = "home_x";
  made.time = static_cast<SimTime>(time_ms * 1e6);
  made.hold = static_cast<SimTime>(hold_ms * 1e6);
  return made;
}

struct HandHeldSwitch {
  HandHeldSwitch() {
    config.name = "home_x";
    config.board = "driver";
    config.connector = scenario::Connector::kLimitA;
    config.kind = &limit_switch_kind();
    config.settings = LimitSwitchConfig{};
    device = limit_switch_kind().build(config, plug);
  }
  bool active_at_ms(double time_ms) const { return plug.line(static_cast<SimTime>(time_ms * 1e6)); }
  scenario::DeviceConfig config;
  LinePlug plug;
  std::unique_ptr<SimDevice> device;
};

TEST(LimitSwitchHand, TakesPressReleaseAndClickAndShowsAsAPageButton) {
  const DeviceKind& kind = limit_switch_kind();
  EXPECT_TRUE(kind.takes(scenario::ActionType::kPress));
  EXPECT_TRUE(kind.takes(scenario::ActionType::kRelease));
  EXPECT_TRUE(kind.takes(scenario::ActionType::kClick));
  EXPECT_FALSE(kind.takes(scenario::ActionType::kTurn));
  EXPECT_EQ(kind.control.type, PageControl::Type::kButton);
}

TEST(LimitSwitchHand, AClickHoldsTheSwitchClosedForItsHold) {
  HandHeldSwitch held;
  held.device->schedule(action(scenario::ActionType::kClick, 10, 100));  // closed 10 … 110 ms
  EXPECT_FALSE(held.active_at_ms(0));
  EXPECT_FALSE(held.active_at_ms(9.999));
  EXPECT_TRUE(held.active_at_ms(10));
  EXPECT_TRUE(held.active_at_ms(109.999));
  EXPECT_FALSE(held.active_at_ms(110));
}

TEST(LimitSwitchHand, APressHoldsItUntilTheRelease) {
  HandHeldSwitch held;
  held.device->schedule(action(scenario::ActionType::kPress, 5));
  held.device->schedule(action(scenario::ActionType::kRelease, 500));
  EXPECT_FALSE(held.active_at_ms(4));
  EXPECT_TRUE(held.active_at_ms(5));
  EXPECT_TRUE(held.active_at_ms(499));
  EXPECT_FALSE(held.active_at_ms(500));
}

}  // namespace
}  // namespace stepdance::sim
