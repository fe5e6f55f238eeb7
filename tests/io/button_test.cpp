// Button: debounce against contact bounce, all four modes, loop-only callbacks, has_changed, invert.
#include "stepdance/io/button.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "hal_manual.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/core/units.hpp"
#include "support/engine_fixture.hpp"

namespace stepdance {
namespace {

constexpr uint8_t kPin = 28;  // IO_D1 on the Driver Module

// Every callback appends one letter, so a test can check which ran and in what order.
std::string events;
void on_press() { events += 'P'; }
void on_release() { events += 'R'; }
void on_toggle() { events += 'T'; }
void on_first() { events += '1'; }
void on_second() { events += '2'; }
void on_third() { events += '3'; }
void on_double() { events += 'D'; }
void on_triple() { events += 'E'; }

void attach_all(Button& button) {
  button.set_callback_on_press(&on_press);
  button.set_callback_on_release(&on_release);
  button.set_callback_on_toggle(&on_toggle);
  button.set_callback_on_first_press(&on_first);
  button.set_callback_on_second_press(&on_second);
  button.set_callback_on_third_press(&on_third);
  button.set_callback_on_doublepress(&on_double);
  button.set_callback_on_triplepress(&on_triple);
}

// Runs n kilohertz ticks (25 frames each).
void run_ms(uint32_t n) { hal_manual::run_frames(n * frames_per_kilohertz_tick()); }

// Holds the pin at each level for one millisecond, in turn.
void drive(const std::vector<bool>& levels) {
  for (bool level : levels) {
    hal_manual::set_pin(kPin, level);
    run_ms(1);
  }
}

// Presses for hold_ms, then releases for gap_ms: the next press lands hold_ms + gap_ms after.
void tap(uint32_t hold_ms = 100, uint32_t gap_ms = 100) {
  hal_manual::set_pin(kPin, true);
  run_ms(hold_ms);
  hal_manual::set_pin(kPin, false);
  run_ms(gap_ms);
}

class ButtonTest : public test_support::EngineFixture {
 protected:
  void SetUp() override {
    EngineFixture::SetUp();
    events.clear();
  }
  // Begins the button on kPin with all callbacks and starts the engine.
  void start(Button& button, uint8_t mode = BUTTON_MODE_STANDARD) {
    ASSERT_EQ(button.begin(kPin), Status::kOk);
    button.set_mode(mode);
    attach_all(button);
    ASSERT_EQ(dance_start(), Status::kOk);
  }
};

TEST_F(ButtonTest, DefaultsToPulldownAndReadsPressedHigh) {
  Button button;
  start(button);
  EXPECT_EQ(hal_manual::pin_mode(kPin), hal::PinMode::kInputPulldown);
  EXPECT_EQ(button.read(), BUTTON_STATE_RELEASED);
  hal_manual::set_pin(kPin, true);
  EXPECT_EQ(button.read_raw(), BUTTON_STATE_PRESSED);
  EXPECT_EQ(button.read(), BUTTON_STATE_RELEASED);  // not sampled yet
  run_ms(1);
  EXPECT_EQ(button.read(), BUTTON_STATE_PRESSED);
}

TEST_F(ButtonTest, StandardModeCallbacksRunOnlyFromTheLoop) {
  Button button;
  start(button);
  hal_manual::set_pin(kPin, true);
  run_ms(1);
  EXPECT_EQ(events, "");  // counted in the kilohertz stage, not called there
  dance_loop();
  EXPECT_EQ(events, "P");
  dance_loop();
  EXPECT_EQ(events, "P");

  hal_manual::set_pin(kPin, false);
  run_ms(50);  // the debounce blackout: ticks 1..50 after the press ignore the pin
  EXPECT_EQ(button.read(), BUTTON_STATE_PRESSED);
  run_ms(1);
  EXPECT_EQ(button.read(), BUTTON_STATE_RELEASED);
  dance_loop();
  EXPECT_EQ(events, "PR");
}

TEST_F(ButtonTest, ContactBounceRegistersExactlyOnePressAndOneRelease) {
  Button button;
  start(button);
  drive({true, false, true, false, true, true});  // bouncing closed
  run_ms(100);
  drive({false, true, false, true, false, false});  // bouncing open
  run_ms(100);
  dance_loop();
  EXPECT_EQ(events, "PR");
  EXPECT_EQ(button.read(), BUTTON_STATE_RELEASED);
}

TEST_F(ButtonTest, ShorterDebounceLetsFastPressesThrough) {
  Button button;
  start(button);
  button.set_debounce_ms(5);
  // Press at tick 0, ticks 1..5 ignored, release at tick 6, ticks 7..11 ignored, press at 12.
  drive({true, false, false, false, false, false, false, true});
  dance_loop();
  EXPECT_EQ(events, "PR");
  run_ms(4);
  dance_loop();
  EXPECT_EQ(events, "PR");
  run_ms(1);
  dance_loop();
  EXPECT_EQ(events, "PRP");
}

TEST_F(ButtonTest, EventsQueuedWhileTheLoopIsSlowAreAllDeliveredInOrder) {
  Button button;
  start(button);
  tap();
  tap();
  tap();
  dance_loop();
  EXPECT_EQ(events, "PRPRPR");
}

TEST_F(ButtonTest, ToggleModeFlipsOnEachPress) {
  Button button;
  start(button, BUTTON_MODE_TOGGLE);
  hal_manual::set_pin(kPin, true);
  run_ms(100);
  EXPECT_EQ(button.read(), BUTTON_STATE_PRESSED);
  hal_manual::set_pin(kPin, false);
  run_ms(100);
  EXPECT_EQ(button.read(), BUTTON_STATE_PRESSED);  // a release does not toggle
  tap();
  EXPECT_EQ(button.read(), BUTTON_STATE_RELEASED);
  dance_loop();  // two toggles before one loop pass: two toggle callbacks
  EXPECT_EQ(events, "TPTR");
  tap();
  dance_loop();
  EXPECT_EQ(events, "TPTRTP");
}

TEST_F(ButtonTest, ThreeStateCyclesAndCallsFirstSecondThird) {
  Button button;
  start(button, BUTTON_MODE_TOGGLE_THREE_STATE);
  tap();
  EXPECT_EQ(button.read(), 1);
  tap();
  EXPECT_EQ(button.read(), 2);
  dance_loop();
  EXPECT_EQ(events, "12");
  tap();
  EXPECT_EQ(button.read(), 0);
  tap();
  EXPECT_EQ(button.read(), 1);
  dance_loop();
  EXPECT_EQ(events, "1231");
}

TEST_F(ButtonTest, MultipressReportsSingleDoubleAndTriple) {
  Button button;
  start(button, BUTTON_MODE_MULTIPRESS);

  tap(100, 100);
  tap(100, 100);  // second press 200 ms after the first
  dance_loop();
  EXPECT_EQ(events, "");  // the window (400 ms after the last press) is still open
  run_ms(300);
  dance_loop();
  EXPECT_EQ(events, "D");

  tap();
  tap();
  tap();
  run_ms(400);
  dance_loop();
  EXPECT_EQ(events, "DE");

  tap();
  run_ms(400);
  dance_loop();
  EXPECT_EQ(events, "DEP");

  for (int i = 0; i < 5; ++i) tap();  // more than three presses count as a triple
  run_ms(400);
  dance_loop();
  EXPECT_EQ(events, "DEPE");
}

TEST_F(ButtonTest, MultipressWindowIsExclusive) {
  Button button;
  start(button, BUTTON_MODE_MULTIPRESS);
  tap(100, 299);  // next press 399 ms later: same gesture
  tap(100, 500);
  dance_loop();
  EXPECT_EQ(events, "D");

  tap(100, 300);  // next press 400 ms later: a new gesture
  tap(100, 500);
  dance_loop();
  EXPECT_EQ(events, "DPP");

  button.set_multipress_window_ms(200);
  tap(100, 99);
  tap(100, 300);
  dance_loop();
  EXPECT_EQ(events, "DPPD");
}

TEST_F(ButtonTest, HasChangedReportsEachChangeOnce) {
  Button button;
  start(button);
  EXPECT_FALSE(button.has_changed());
  hal_manual::set_pin(kPin, true);
  run_ms(1);
  EXPECT_TRUE(button.has_changed());
  EXPECT_FALSE(button.has_changed());
  dance_loop();  // callbacks do not consume it
  hal_manual::set_pin(kPin, false);
  run_ms(60);
  EXPECT_TRUE(button.has_changed());
  EXPECT_FALSE(button.has_changed());
}

TEST_F(ButtonTest, InvertFlipsTheMeaningWithoutAnEvent) {
  Button button;
  ASSERT_EQ(button.begin(kPin, arduino_pin_mode::kInputPullup), Status::kOk);
  attach_all(button);
  EXPECT_EQ(hal_manual::pin_mode(kPin), hal::PinMode::kInputPullup);
  EXPECT_EQ(button.read(), BUTTON_STATE_PRESSED);  // pulled up and not inverted: "pressed"
  button.set_invert();
  EXPECT_EQ(button.read(), BUTTON_STATE_RELEASED);
  EXPECT_EQ(button.read_raw(), BUTTON_STATE_RELEASED);
  ASSERT_EQ(dance_start(), Status::kOk);
  run_ms(10);
  dance_loop();
  EXPECT_EQ(events, "");
  EXPECT_FALSE(button.has_changed());

  hal_manual::set_pin(kPin, false);  // a switch to ground closes
  run_ms(1);
  EXPECT_EQ(button.read(), BUTTON_STATE_PRESSED);
  dance_loop();
  EXPECT_EQ(events, "P");

  button.clear_invert();
  EXPECT_EQ(button.read(), BUTTON_STATE_RELEASED);
  run_ms(100);
  dance_loop();
  EXPECT_EQ(events, "P");
}

TEST_F(ButtonTest, BeginAcceptsInputModesOnly) {
  Button a;
  Button b;
  Button c;
  Button d;
  EXPECT_EQ(a.begin(kPin, uint8_t{1}), Status::kBadArgument);  // Arduino OUTPUT
  EXPECT_EQ(b.begin(kPin, hal::PinMode::kOutput), Status::kBadArgument);
  EXPECT_EQ(c.begin(200), Status::kNoSuchPin);
  EXPECT_EQ(engine().count(Stage::kKilohertz), 0u);
  EXPECT_EQ(d.begin(kPin, arduino_pin_mode::kInput), Status::kOk);
  EXPECT_EQ(hal_manual::pin_mode(kPin), hal::PinMode::kInput);
  EXPECT_EQ(engine().count(Stage::kKilohertz), 1u);
  EXPECT_EQ(engine().count(Stage::kLoop), 1u);
}

}  // namespace
}  // namespace stepdance
