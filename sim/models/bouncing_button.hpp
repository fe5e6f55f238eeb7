// A push button whose contacts bounce for a while after every press and release.
#pragma once

#include <cstdint>
#include <vector>

#include "common/edges.hpp"
#include "common/sim_time.hpp"

namespace stepdance::sim {

/// Settings of one button.
struct ButtonSettings {
  /// How long the contacts bounce after each press or release (ns); 0 = clean edges.
  SimTime bounce = 2 * kMillisecond;
  /// Line level while pressed: true for a button to 3V3 with a pull-down (the kit's wiring).
  bool pressed_level = true;
  /// Seed of the bounce patterns (the scenario seed, or one derived from it).
  uint64_t seed = 1;
};

/// A button driven by scheduled presses and releases. Each transition at time t changes the line
/// to the new level at t, then bounces: 1 to 3 short pulses back to the old level, at seeded
/// random times strictly inside (t, t + bounce); from t + bounce on the line is settled. A bounce
/// window is cut short by the next transition. The pattern of a transition depends only on the
/// seed and its time, so the same schedule always gives the same edges. A press while already
/// pressed (or a release while released) changes nothing.
class BouncingButton {
 public:
  explicit BouncingButton(const ButtonSettings& settings = {});

  /// Schedules a press at `time` (ns).
  void press(SimTime time);
  /// Schedules a release at `time` (ns).
  void release(SimTime time);
  /// Schedules a press at `time` and a release `hold` ns later.
  void click(SimTime time, SimTime hold);

  /// Electrical line level at `time`, bounce included. O(log edges).
  bool level_at(SimTime time) const;
  /// Whether the button is held down at `time`, ignoring bounce.
  bool pressed_at(SimTime time) const;
  /// Line level before the first transition (the released level).
  bool idle_level() const { return !settings_.pressed_level; }
  /// Every change of the line level, in time order, bounce included.
  const EdgeList& edges() const;

 private:
  struct Transition {
    SimTime time;
    bool pressed;
  };
  void schedule(SimTime time, bool pressed);
  void rebuild_edges() const;
  /// Adds the bounce pulses of a transition to `level` at `start`, inside (start, window_end).
  void add_bounce(SimTime start, SimTime window_end, bool level) const;

  ButtonSettings settings_;
  /// Transitions sorted by time (stable).
  std::vector<Transition> transitions_;
  mutable EdgeList edges_;
  mutable bool edges_stale_ = false;
};

}  // namespace stepdance::sim
