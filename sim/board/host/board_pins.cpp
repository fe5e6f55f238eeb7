// BoardPins: modes, driven levels, driven inputs and change listeners.
#include "board/host/board_pins.hpp"

#include "stepdance/core/status.hpp"

namespace stepdance::sim {

bool BoardPins::level(uint8_t pin, SimTime now_ns) const {
  const PinState& state = pins_.at(pin);
  if (state.mode == STEPDANCE_PIN_OUTPUT) return state.driven_level;
  if (state.source) return state.source(now_ns);
  return state.mode == STEPDANCE_PIN_INPUT_PULLUP;
}

// Listeners hear a change of mode between output and input too (the pin stops or starts driving).
int BoardPins::set_mode(uint8_t pin, int mode, SimTime now_ns) {
  if (pin >= kPins || mode < STEPDANCE_PIN_INPUT || mode > STEPDANCE_PIN_OUTPUT) {
    return static_cast<int>(Status::kBadArgument);
  }
  const bool was_output = pins_[pin].mode == STEPDANCE_PIN_OUTPUT;
  pins_[pin].mode = mode;
  if (was_output != (mode == STEPDANCE_PIN_OUTPUT)) notify(pin, now_ns);
  return static_cast<int>(Status::kOk);
}

void BoardPins::write(uint8_t pin, bool high, SimTime now_ns) {
  if (pin >= kPins) return;
  const bool changed = pins_[pin].driven_level != high;
  pins_[pin].driven_level = high;
  if (changed && pins_[pin].mode == STEPDANCE_PIN_OUTPUT) notify(pin, now_ns);
}

void BoardPins::drive_high(uint8_t pin, SimTime now_ns) {
  pins_[pin].mode = STEPDANCE_PIN_OUTPUT;
  pins_[pin].driven_level = true;
  notify(pin, now_ns);
}

void BoardPins::notify(uint8_t pin, SimTime now_ns) const {
  const PinState& state = pins_[pin];
  const bool driven = state.mode == STEPDANCE_PIN_OUTPUT;
  for (const Listener& listener : state.listeners) listener(now_ns, state.driven_level, driven);
}

}  // namespace stepdance::sim
