// Button: 1 kHz sampling with a debounce blackout, per-mode state machines, loop-side delivery.
#include "stepdance/io/button.hpp"

namespace stepdance {
namespace {

constexpr uint8_t kNoButtonPin = 255;
constexpr uint8_t kThreeStates = 3;
constexpr uint8_t kLongestGesture = 3;  // presses beyond the third still count as a triple

bool valid_mode(uint8_t mode) { return mode <= BUTTON_MODE_MULTIPRESS; }

}  // namespace

// Default pull-down: a Stepdance button wired to 3.3 V reads high when pressed, and an open pin
// reads released rather than floating.
Status Button::begin(uint8_t pin) { return begin(pin, hal::PinMode::kInputPulldown); }

// Accepts the Arduino pinMode constants (INPUT, INPUT_PULLUP, INPUT_PULLDOWN) so sketches written
// against the original interface compile; OUTPUT or anything else is refused.
Status Button::begin(uint8_t pin, uint8_t arduino_mode) {
  switch (arduino_mode) {
    case arduino_pin_mode::kInput: return begin(pin, hal::PinMode::kInput);
    case arduino_pin_mode::kInputPullup: return begin(pin, hal::PinMode::kInputPullup);
    case arduino_pin_mode::kInputPulldown: return begin(pin, hal::PinMode::kInputPulldown);
    default: return Status::kBadArgument;
  }
}

// The first level is sampled before the tick starts so a button held at power-up is not seen as
// a press edge. Sampling runs at 1 kHz (debounce counted in ms); callbacks run in loop context.
Status Button::begin(uint8_t pin, hal::PinMode mode) {
  if (mode == hal::PinMode::kOutput) return Status::kBadArgument;
  const Status configured = hal::gpio_mode(pin, mode);
  if (configured != Status::kOk) return configured;
  {
    hal::CriticalSection guard;
    pin_ = pin;
    level_ = sample_level();
    blackout_remaining_ms_ = 0;
  }
  set_mode(mode_);
  const Status tick = register_in(Stage::kKilohertz);
  if (tick != Status::kOk) return tick;
  return register_in(Stage::kLoop);
}

// Changing mode resynchronises everything: the state follows the pin level in the level-following
// modes, and every counted but undelivered change or gesture is dropped, so the new mode never
// fires callbacks for events that happened under the old one.
void Button::set_mode(uint8_t mode) {
  if (!valid_mode(mode)) return;
  hal::CriticalSection guard;
  mode_ = mode;
  const bool follows_level = mode == BUTTON_MODE_STANDARD || mode == BUTTON_MODE_MULTIPRESS;
  state_ = follows_level && level_ ? BUTTON_STATE_PRESSED : BUTTON_STATE_RELEASED;
  delivered_state_ = state_;
  state_changes_delivered_ = state_changes_;
  for (uint8_t kind = 0; kind < kLongestGesture; ++kind) gestures_delivered_[kind] = gestures_[kind];
  gesture_presses_ = 0;
}

// Inverting flips meaning, not the pin: no edge is counted. delivered_state_ is flipped too so the
// next real edge still delivers the right press/release instead of repeating the current state.
void Button::set_inverted(bool inverted) {
  if (inverted == inverted_) return;
  hal::CriticalSection guard;
  inverted_ = inverted;
  level_ = !level_;  // same pin level, opposite meaning: not an edge
  if (mode_ == BUTTON_MODE_STANDARD || mode_ == BUTTON_MODE_MULTIPRESS) {
    state_ = level_ ? BUTTON_STATE_PRESSED : BUTTON_STATE_RELEASED;
    delivered_state_ = delivered_state_ == BUTTON_STATE_PRESSED ? BUTTON_STATE_RELEASED : BUTTON_STATE_PRESSED;
  }
}

bool Button::sample_level() const { return pin_ != kNoButtonPin && hal::gpio_read(pin_) != inverted_; }

uint8_t Button::read_raw() const { return sample_level() ? BUTTON_STATE_PRESSED : BUTTON_STATE_RELEASED; }

// Polling alternative to callbacks: true once per batch of state changes or completed gestures
// since the previous call. Loop context only (it updates its own snapshot).
bool Button::has_changed() {
  const uint32_t total = state_changes_ + gestures_[0] + gestures_[1] + gestures_[2];
  const bool changed = total != changes_seen_by_has_changed_;
  changes_seen_by_has_changed_ = total;
  return changed;
}

// Kilohertz-tick context (interrupt). Debounce is a blackout, not a filter: the first edge is
// taken at once (no latency on a press) and the pin is ignored for debounce_ms_ afterwards, which
// swallows contact bounce. The multipress window is counted even during the blackout.
void Button::sample() {
  if (pin_ == kNoButtonPin) return;
  count_multipress_window();  // before the edge, so a late press opens a new gesture
  if (blackout_remaining_ms_ > 0) {
    blackout_remaining_ms_ = blackout_remaining_ms_ - 1;
    return;
  }
  const bool pressed = sample_level();
  if (pressed == level_) return;
  level_ = pressed;
  blackout_remaining_ms_ = debounce_ms_;
  on_level_change(pressed);
}

// A gesture ends when multipress_window_ms_ passes without another press; it is then counted as a
// single, double or triple press (kind = presses − 1). Tick context.
void Button::count_multipress_window() {
  if (mode_ != BUTTON_MODE_MULTIPRESS || gesture_presses_ == 0) return;
  ms_since_press_ = ms_since_press_ + 1;
  if (ms_since_press_ < multipress_window_ms_) return;
  const uint8_t kind = static_cast<uint8_t>(gesture_presses_ - 1);
  gestures_[kind] = gestures_[kind] + 1;
  gesture_presses_ = 0;
}

// Tick context: only counters change here; callbacks are fired later from loop context by
// deliver_events(). Toggle modes advance on the press edge only; multipress counts presses and
// restarts the gesture window on each.
void Button::on_level_change(bool pressed) {
  switch (mode_) {
    case BUTTON_MODE_STANDARD:
      state_ = pressed ? BUTTON_STATE_PRESSED : BUTTON_STATE_RELEASED;
      state_changes_ = state_changes_ + 1;
      return;
    case BUTTON_MODE_TOGGLE:
    case BUTTON_MODE_TOGGLE_THREE_STATE:
      if (!pressed) return;
      state_ = next_state(state_);
      state_changes_ = state_changes_ + 1;
      return;
    case BUTTON_MODE_MULTIPRESS:
      state_ = pressed ? BUTTON_STATE_PRESSED : BUTTON_STATE_RELEASED;
      if (!pressed) return;
      if (gesture_presses_ < kLongestGesture) gesture_presses_ = gesture_presses_ + 1;
      ms_since_press_ = 0;
      return;
    default: return;
  }
}

// Three-state toggle cycles 0 → 1 → 2 → 0; every other mode alternates pressed/released.
uint8_t Button::next_state(uint8_t state) const {
  if (mode_ == BUTTON_MODE_TOGGLE_THREE_STATE) return static_cast<uint8_t>((state + 1) % kThreeStates);
  return state == BUTTON_STATE_PRESSED ? BUTTON_STATE_RELEASED : BUTTON_STATE_PRESSED;
}

void Button::deliver_events() {
  deliver_state_changes();
  deliver_gestures();
}

void Button::deliver_state_changes() {
  // Re-reads the counter each time: a callback may call set_mode(), which resynchronises.
  while (state_changes_delivered_ != state_changes_) {
    ++state_changes_delivered_;
    delivered_state_ = next_state(delivered_state_);
    fire_state_callbacks(delivered_state_);
  }
}

// Three-state toggle fires one callback per state reached; a plain toggle fires on_toggle and then
// the press/release callback for the new state (the fall-through is intended).
void Button::fire_state_callbacks(uint8_t state) {
  switch (mode_) {
    case BUTTON_MODE_TOGGLE_THREE_STATE:
      if (state == 1) call(on_first_press_);
      if (state == 2) call(on_second_press_);
      if (state == 0) call(on_third_press_);
      return;
    case BUTTON_MODE_TOGGLE: call(on_toggle_); [[fallthrough]];
    default: call(state == BUTTON_STATE_PRESSED ? on_press_ : on_release_); return;
  }
}

// Loop context: one callback per counted gesture, in order single, double, triple. Counters are
// compared, not reset, so the tick may keep counting while this runs.
void Button::deliver_gestures() {
  const Callback callbacks[kLongestGesture] = {on_press_, on_doublepress_, on_triplepress_};
  for (uint8_t kind = 0; kind < kLongestGesture; ++kind) {
    while (gestures_delivered_[kind] != gestures_[kind]) {
      ++gestures_delivered_[kind];
      call(callbacks[kind]);
    }
  }
}

void Button::call(Callback callback) {
  if (callback != nullptr) callback();
}

}  // namespace stepdance
