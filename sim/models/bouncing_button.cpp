// BouncingButton: transition schedule expanded into seeded bounce edges.
#include "models/bouncing_button.hpp"

#include <algorithm>
#include <iterator>

#include "models/random_stream.hpp"

namespace stepdance::sim {

namespace {
/// Bounce pulses per transition: 1 to this many.
constexpr uint64_t kMaxBouncePulses = 3;
}  // namespace

BouncingButton::BouncingButton(const ButtonSettings& settings) : settings_(settings) {}

void BouncingButton::press(SimTime time) { schedule(time, true); }

void BouncingButton::release(SimTime time) { schedule(time, false); }

void BouncingButton::click(SimTime time, SimTime hold) {
  press(time);
  release(time + std::max<SimTime>(hold, 0));
}

void BouncingButton::schedule(SimTime time, bool pressed) {
  const auto at = std::upper_bound(transitions_.begin(), transitions_.end(), time,
                                   [](SimTime t, const Transition& transition) { return t < transition.time; });
  transitions_.insert(at, Transition{time, pressed});
  edges_stale_ = true;
}

bool BouncingButton::pressed_at(SimTime time) const {
  const auto after = std::upper_bound(transitions_.begin(), transitions_.end(), time,
                                      [](SimTime t, const Transition& transition) { return t < transition.time; });
  return after != transitions_.begin() && std::prev(after)->pressed;
}

const EdgeList& BouncingButton::edges() const {
  if (edges_stale_) rebuild_edges();
  return edges_;
}

bool BouncingButton::level_at(SimTime time) const {
  const EdgeList& all = edges();
  const auto after =
      std::upper_bound(all.begin(), all.end(), time, [](SimTime t, const Edge& edge) { return t < edge.time; });
  return after == all.begin() ? idle_level() : std::prev(after)->level;
}

void BouncingButton::rebuild_edges() const {
  edges_.clear();
  // Effective transitions only: each one flips the settled state.
  std::vector<Transition> effective;
  bool pressed = false;
  for (const Transition& transition : transitions_) {
    if (transition.pressed == pressed) continue;
    pressed = transition.pressed;
    if (!effective.empty() && effective.back().time == transition.time) {
      effective.pop_back();  // a press and release at the same instant cancel out
      continue;
    }
    effective.push_back(transition);
  }
  for (size_t i = 0; i < effective.size(); ++i) {
    const bool level = effective[i].pressed ? settings_.pressed_level : !settings_.pressed_level;
    const SimTime start = effective[i].time;
    SimTime window_end = start + std::max<SimTime>(settings_.bounce, 0);
    if (i + 1 < effective.size()) window_end = std::min(window_end, effective[i + 1].time);
    edges_.push_back(Edge{start, level});
    add_bounce(start, window_end, level);
  }
  edges_stale_ = false;
}

void BouncingButton::add_bounce(SimTime start, SimTime window_end, bool level) const {
  // Candidate instants are start + 1 .. window_end − 1; each toggle gets its own equal share of
  // them, so the toggles are strictly increasing and an even number of them ends on `level`.
  const SimTime room = window_end - start - 1;
  if (room < 2) return;
  RandomStream random(mix_seed(settings_.seed, static_cast<uint64_t>(start)));
  uint64_t pulses = 1 + random.below(kMaxBouncePulses);
  pulses = std::min<uint64_t>(pulses, static_cast<uint64_t>(room) / 2);
  const uint64_t toggles = 2 * pulses;
  bool current = level;
  for (uint64_t j = 0; j < toggles; ++j) {
    const SimTime low = start + 1 + static_cast<SimTime>(j * static_cast<uint64_t>(room) / toggles);
    const SimTime high = start + 1 + static_cast<SimTime>((j + 1) * static_cast<uint64_t>(room) / toggles);
    current = !current;
    edges_.push_back(Edge{low + static_cast<SimTime>(random.below(static_cast<uint64_t>(high - low))), current});
  }
}

}  // namespace stepdance::sim
