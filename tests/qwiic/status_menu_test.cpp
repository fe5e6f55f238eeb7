// StatusMenu: cursor, editing a parameter in steps between limits, actions, rows shown.
#include "stepdance/qwiic/status_menu.hpp"

#include <gtest/gtest.h>

#include <array>
#include <string>

#include "qwiic/qwiic_fixture.hpp"

namespace stepdance {
namespace {

// Just enough of a Twist (ID, count, status) and an OLED (acknowledges) on QWIIC1.
struct FakeBus {
  int16_t count = 0;
  uint8_t status = 0;
  hal::I2cResult answer(const hal_manual::I2cRecord& t, uint8_t* read, uint16_t n) {
    if (t.address == 0x3C) return hal::I2cResult::kOk;
    if (t.address != 0x3F) return hal::I2cResult::kAddressNack;
    std::array<uint8_t, 0x20> regs{};
    regs[0x00] = 0x5C;
    regs[0x01] = status;
    regs[0x05] = static_cast<uint8_t>(count & 0xFF);
    regs[0x06] = static_cast<uint8_t>((count >> 8) & 0xFF);
    if (t.written.size() == 2 && t.written[0] == 0x01) status = t.written[1];  // clear
    for (uint16_t i = 0; i < n; ++i) read[i] = regs[t.written[0] + i];
    return hal::I2cResult::kOk;
  }
};

ControlParameter speed = 1.0f;
float changed_to = 0;
int actions_run = 0;
float cpu_load() { return 0.25f; }

class StatusMenuTest : public test_support::QwiicFixture {
 protected:
  void SetUp() override {
    QwiicFixture::SetUp();
    hal_manual::i2c_set_responder(
        [this](const hal_manual::I2cRecord& t, uint8_t* r, uint16_t n) { return bus.answer(t, r, n); });
    speed = 1.0f;
    changed_to = 0;
    actions_run = 0;
    ASSERT_EQ(display.begin(), Status::kOk);
    ASSERT_EQ(knob.begin(), Status::kOk);
    ASSERT_EQ(menu.begin(&display, &knob, "STEPDANCE"), Status::kOk);
    ASSERT_EQ(menu.add_value("CPU", &cpu_load, 2), Status::kOk);
    ASSERT_EQ(menu.add_parameter("SPEED", &speed, 0.5f, 0.0f, 2.0f, 1, [](float v) { changed_to = v; }), Status::kOk);
    ASSERT_EQ(menu.add_action("PEN UP", [] { ++actions_run; }), Status::kOk);
    loop_passes(500);  // 100 ms: knob identified and polled, screen drawn
  }
  void turn(int detents) {
    bus.count = static_cast<int16_t>(bus.count + detents);
    loop_passes(200);
  }
  void click() {
    bus.status |= 0x04;
    loop_passes(200);
  }
  std::string row(uint8_t r) const { return menu.row_text(r); }
  FakeBus bus;
  OledDisplay display;
  QwiicTwist knob;
  StatusMenu menu;
};

TEST_F(StatusMenuTest, ShowsTitleValuesAndCursor) {
  EXPECT_EQ(row(0), "STEPDANCE");
  EXPECT_EQ(row(1), " CPU 0.25");
  EXPECT_EQ(row(2), ">SPEED 1.0");  // the first selectable item
  EXPECT_EQ(row(3), " PEN UP");
}

TEST_F(StatusMenuTest, ClickEditsTurnsStepAndClampAnotherClickEnds) {
  click();
  EXPECT_TRUE(menu.editing());
  EXPECT_EQ(row(2), "*SPEED 1.0");
  turn(1);
  EXPECT_FLOAT_EQ(speed, 1.5f);
  EXPECT_FLOAT_EQ(changed_to, 1.5f);
  turn(5);  // 1.5 + 2.5 → clamped to 2.0
  EXPECT_FLOAT_EQ(speed, 2.0f);
  EXPECT_EQ(row(2), "*SPEED 2.0");
  turn(-6);  // → −1.0 → clamped to 0
  EXPECT_FLOAT_EQ(speed, 0.0f);
  click();
  EXPECT_FALSE(menu.editing());
  turn(1);
  EXPECT_FLOAT_EQ(speed, 0.0f);  // turning now moves the cursor instead
  EXPECT_EQ(row(3), ">PEN UP");
}

TEST_F(StatusMenuTest, CursorSkipsValuesStopsAtTheEndsAndClickRunsActions) {
  turn(-3);
  EXPECT_EQ(menu.selected(), 1);  // the value above is not selectable
  turn(4);
  EXPECT_EQ(menu.selected(), 2);
  click();
  EXPECT_EQ(actions_run, 1);
  EXPECT_FALSE(menu.editing());
}

TEST_F(StatusMenuTest, ItemsBeyondCapacityAreRefused) {
  StatusMenu full;
  ASSERT_EQ(full.begin(&display, nullptr, "X"), Status::kOk);
  for (uint8_t i = 0; i < StatusMenu::kMaxItems; ++i) ASSERT_EQ(full.add_value("V", &cpu_load, 1), Status::kOk);
  EXPECT_EQ(full.add_value("V", &cpu_load, 1), Status::kFull);
  EXPECT_EQ(full.add_parameter("P", &speed, 0, 0, 1, 1), Status::kBadArgument);
}

}  // namespace
}  // namespace stepdance
