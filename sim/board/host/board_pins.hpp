// A board's digital pins: the mode the sketch gives each, the level it drives, what an external
// device drives into an input, and who listens to an output.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "board/abi/board_abi.h"
#include "common/sim_time.hpp"
#include "stepdance/boards/board.hpp"

namespace stepdance::sim {

/// The digital pins of one board, numbered as the Teensy's (the largest Teensy's count). Times
/// are the board's (SimBoard::now()), passed in. Context: host, on the simulation's thread.
class BoardPins {
 public:
  static constexpr uint8_t kPins = kTeensy41.highest_pin + 1;
  /// What an external device drives into an input pin, as a function of simulated time.
  using LevelSource = std::function<bool(SimTime)>;
  /// Told when an output pin changes: (time, level, whether the pin is driven as an output).
  using Listener = std::function<void(SimTime, bool level, bool driven)>;

  // ---- wiring ----
  /// An external device drives input pin `pin` (replacing any before).
  void connect_input(uint8_t pin, LevelSource level) { pins_.at(pin).source = std::move(level); }
  /// Calls `listener` whenever the sketch changes pin `pin`'s output.
  void on_change(uint8_t pin, Listener listener) { pins_.at(pin).listeners.push_back(std::move(listener)); }

  // ---- the program side ----
  /// Configures `pin` (a StepdancePinMode); kBadArgument for a pin the board lacks.
  int set_mode(uint8_t pin, int mode, SimTime now_ns);
  void write(uint8_t pin, bool high, SimTime now_ns);
  /// Drives `pin` high as an output (a driver's ENABLE in the safe state) and tells its listeners.
  void drive_high(uint8_t pin, SimTime now_ns);
  /// The level the sketch would read on `pin` at `now_ns` (or that it drives): its driven level,
  /// else its device's, else the pull-up's.
  bool level(uint8_t pin, SimTime now_ns) const;

 private:
  struct PinState {
    int mode = STEPDANCE_PIN_INPUT;
    bool driven_level = false;
    LevelSource source;
    std::vector<Listener> listeners;
  };
  void notify(uint8_t pin, SimTime now_ns) const;

  std::array<PinState, kPins> pins_{};
};

}  // namespace stepdance::sim
