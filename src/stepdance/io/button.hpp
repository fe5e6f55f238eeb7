// Button: a debounced push button or switch with standard, toggle, three-state and multi-press modes.
#pragma once

#include <stdint.h>

#include "stepdance/core/block.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/hal/hal.hpp"
#include "stepdance/io/arduino_pin_mode.hpp"

namespace stepdance {

/// How presses become a state and events.
enum ButtonMode : uint8_t {
  BUTTON_MODE_STANDARD = 0,            ///< state follows the button: press / release events
  BUTTON_MODE_TOGGLE = 1,              ///< each press flips the state: toggle + press / release
  BUTTON_MODE_TOGGLE_THREE_STATE = 2,  ///< each press steps 0 → 1 → 2 → 0: first/second/third
  BUTTON_MODE_MULTIPRESS = 3,          ///< presses grouped in a window: single/double/triple
};

/// Logical button states returned by read() (TOGGLE_THREE_STATE also returns 2).
constexpr uint8_t BUTTON_STATE_RELEASED = 0;
constexpr uint8_t BUTTON_STATE_PRESSED = 1;

/// A button on a digital pin, sampled every millisecond (kilohertz stage).
///
/// Debounce: once a change of level is accepted, the pin is ignored for the debounce time
/// (default 50 ms), so contact bounce after a press or release produces no extra event.
/// Pressed means the pin reads high (a button to 3V3 with the pull-down), unless set_invert().
///
/// Events are counted in the kilohertz stage and delivered by dance_loop(): callbacks never run
/// in an interrupt, and none is lost when the loop is slow (two toggles between two loop passes
/// give two toggle callbacks, in order).
///
/// Mode by mode (callbacks without a function set are skipped):
///  - STANDARD: read() = debounced level; on_press / on_release.
///  - TOGGLE: each press flips read(); on_toggle, then on_press (now 1) or on_release (now 0).
///  - TOGGLE_THREE_STATE: each press steps read() 0 → 1 → 2 → 0 and calls on_first_press,
///    on_second_press or on_third_press for the new state 1, 2 or 0.
///  - MULTIPRESS: presses less than the window apart (default 400 ms) form one gesture; when
///    the window after the last press closes: 1 press → on_press, 2 → on_doublepress,
///    3 or more → on_triplepress. read() = debounced level.
/// The original library never fired the last two modes; both work here.
class Button : public Block {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "Button"; }
  /// A user callback: no arguments, called from dance_loop().
  using Callback = void (*)();

  Button() = default;

  /// Starts sampling `pin` with the internal pull-down (buttons on our boards switch to 3V3).
  /// The original defaulted to the pull-up, which reads a released button as pressed.
  /// Registers in the kilohertz and loop stages. kNoSuchPin from the HAL. Context: loop.
  Status begin(uint8_t pin);
  /// As begin(pin), with an Arduino pin mode: INPUT (0), INPUT_PULLUP (2), INPUT_PULLDOWN (3).
  /// kBadArgument for any other mode. Context: loop.
  Status begin(uint8_t pin, uint8_t arduino_mode);
  /// As begin(pin), with a HAL pin mode (any input mode; kOutput is kBadArgument).
  /// Context: loop.
  Status begin(uint8_t pin, hal::PinMode mode);

  /// Chooses the mode (BUTTON_MODE_*). The state restarts at the debounced level (STANDARD,
  /// MULTIPRESS) or 0 (the toggle modes); events not yet delivered are dropped. Context: loop.
  void set_mode(uint8_t mode);
  /// Milliseconds the pin is ignored after an accepted change (default 50). Context: loop.
  void set_debounce_ms(uint32_t ms) { debounce_ms_ = ms; }
  /// Longest gap between two presses of one MULTIPRESS gesture, in ms (default 400).
  /// Context: loop.
  void set_multipress_window_ms(uint32_t ms) { multipress_window_ms_ = ms; }
  /// Pressed = pin low from now on. The stored level flips with it, so no event fires.
  /// Context: loop.
  void set_invert() { set_inverted(true); }
  /// Pressed = pin high (the default). Context: loop.
  void clear_invert() { set_inverted(false); }

  /// The logical state: BUTTON_STATE_PRESSED / _RELEASED, or 0..2 in TOGGLE_THREE_STATE.
  /// Context: any.
  uint8_t read() const { return state_; }
  /// Whether the button is pressed at this instant: the pin level with the inversion applied,
  /// without debouncing (BUTTON_STATE_PRESSED / _RELEASED). Context: any.
  uint8_t read_raw() const;
  /// True if the state changed (or a MULTIPRESS gesture completed) since the previous call;
  /// independent of callbacks (the original cleared it whenever a callback ran). Context: loop.
  bool has_changed();

  /// Callback setters: each runs from dance_loop() (never in an interrupt) once per event of
  /// its kind, as described in the class comment; nullptr removes it. Context: loop.
  /// Press: STANDARD and TOGGLE (state now pressed), and a single MULTIPRESS press.
  void set_callback_on_press(Callback callback) { on_press_ = callback; }
  /// Release: STANDARD and TOGGLE (state now released). Context: loop.
  void set_callback_on_release(Callback callback) { on_release_ = callback; }
  /// Every TOGGLE flip, before the press/release callback. Context: loop.
  void set_callback_on_toggle(Callback callback) { on_toggle_ = callback; }
  /// TOGGLE_THREE_STATE reaching state 1. Context: loop.
  void set_callback_on_first_press(Callback callback) { on_first_press_ = callback; }
  /// TOGGLE_THREE_STATE reaching state 2. Context: loop.
  void set_callback_on_second_press(Callback callback) { on_second_press_ = callback; }
  /// TOGGLE_THREE_STATE returning to state 0. Context: loop.
  void set_callback_on_third_press(Callback callback) { on_third_press_ = callback; }
  /// A MULTIPRESS gesture of two presses. Context: loop.
  void set_callback_on_doublepress(Callback callback) { on_doublepress_ = callback; }
  /// A MULTIPRESS gesture of three or more presses. Context: loop.
  void set_callback_on_triplepress(Callback callback) { on_triplepress_ = callback; }

  /// Millisecond work: sample, debounce, update the state, count events. Called by the engine.
  /// Context: kilohertz ISR.
  void run_kilohertz() override { sample(); }
  /// Delivers the events counted since the last pass to the callbacks. Called by dance_loop().
  /// Context: loop.
  void loop() override { deliver_events(); }

 private:
  // Virtuals stay inline (no key function): see Block.
  void sample();
  void deliver_events();
  bool sample_level() const;
  void on_level_change(bool pressed);
  void count_multipress_window();
  void deliver_state_changes();
  void deliver_gestures();
  void set_inverted(bool inverted);
  uint8_t next_state(uint8_t state) const;
  void fire_state_callbacks(uint8_t state);
  static void call(Callback callback);

  Callback on_press_ = nullptr;
  Callback on_release_ = nullptr;
  Callback on_toggle_ = nullptr;
  Callback on_first_press_ = nullptr;
  Callback on_second_press_ = nullptr;
  Callback on_third_press_ = nullptr;
  Callback on_doublepress_ = nullptr;
  Callback on_triplepress_ = nullptr;

  uint32_t debounce_ms_ = 50;
  uint32_t multipress_window_ms_ = 400;

  // Written by the kilohertz stage only.
  volatile uint32_t state_changes_ = 0;  // every change of state_, in order
  volatile uint32_t gestures_[3] = {};   // completed single / double / triple presses
  volatile uint32_t blackout_remaining_ms_ = 0;
  volatile uint32_t ms_since_press_ = 0;
  volatile uint8_t gesture_presses_ = 0;
  volatile uint8_t state_ = BUTTON_STATE_RELEASED;
  volatile bool level_ = false;  // debounced "pressed" level

  // Owned by the loop.
  uint32_t state_changes_delivered_ = 0;
  uint32_t gestures_delivered_[3] = {};
  uint32_t changes_seen_by_has_changed_ = 0;
  uint8_t delivered_state_ = BUTTON_STATE_RELEASED;

  uint8_t mode_ = BUTTON_MODE_STANDARD;
  uint8_t pin_ = 255;
  bool inverted_ = false;
};

}  // namespace stepdance
