// Cable: per-window STEP/DIR transform (delay, stretch, glitches) with its counters.
#include "models/cable.hpp"

#include <algorithm>
#include <limits>
#include <vector>

namespace stepdance::sim {

namespace {
constexpr SimTime kNever = std::numeric_limits<SimTime>::max();

/// One STEP pulse in input time; `fall` is kNever while it is still high.
struct Pulse {
  SimTime rise;
  SimTime fall;
  bool rise_sent;
};
}  // namespace

Cable::Cable(const CableSettings& settings) : settings_(settings) {}

PortWaveform Cable::transmit(const PortWaveform& input, SimTime window_start, SimTime window_end) {
  // Pair the STEP edges into pulses, continuing a pulse left open by the previous window.
  std::vector<Pulse> pulses;
  bool high = open_pulse_;
  Pulse current{open_rise_, kNever, open_pulse_};
  for (const Edge& edge : input.step) {
    if (edge.level == high) continue;
    high = edge.level;
    if (high) {
      current = Pulse{edge.time, kNever, false};
      ++counters_.pulses_in;
    } else {
      current.fall = edge.time;
      pulses.push_back(current);
    }
  }
  if (high) pulses.push_back(current);

  // Stretch, then merge pulses that now touch.
  std::vector<Pulse> shaped;
  for (Pulse pulse : pulses) {
    if (pulse.fall != kNever) {
      pulse.fall += settings_.stretch;
      if (pulse.rise_sent) {
        // Its rising edge went out with an earlier window: the fall cannot move before this one.
        pulse.fall = std::max({pulse.fall, pulse.rise + 1, window_start});
      } else if (pulse.fall <= pulse.rise) {
        ++counters_.pulses_removed;
        continue;
      }
    }
    if (!pulse.rise_sent && pulse.rise <= last_fall_) pulse.rise = last_fall_ + 1;
    if (!shaped.empty() && pulse.rise <= shaped.back().fall) {
      shaped.back().fall = std::max(shaped.back().fall, pulse.fall);
      ++counters_.pulses_merged;
      continue;
    }
    if (pulse.fall != kNever && pulse.fall <= pulse.rise) pulse.fall = pulse.rise + 1;
    shaped.push_back(pulse);
  }

  // Glitch slots whose pulse fits in the window and touches no real pulse.
  std::vector<SimTime> glitches;
  if (settings_.glitch_every > 0 && settings_.glitch_width > 0) {
    SimTime slot = std::max<SimTime>(1, (window_start + settings_.glitch_every - 1) / settings_.glitch_every);
    for (SimTime start = slot * settings_.glitch_every; start < window_end;
         start = (++slot) * settings_.glitch_every) {
      const SimTime end = start + settings_.glitch_width;
      const bool clear = end < window_end && start > last_fall_ && std::none_of(shaped.begin(), shaped.end(), [&](const Pulse& pulse) {
                           return !(end < pulse.rise || start > pulse.fall);
                         });
      if (clear) {
        glitches.push_back(start);
        ++counters_.glitches_injected;
      } else {
        ++counters_.glitches_skipped;
      }
    }
  }

  // Emit, delayed.
  PortWaveform output;
  const SimTime delay = settings_.delay;
  for (const Pulse& pulse : shaped) {
    if (!pulse.rise_sent) {
      output.step.push_back(Edge{pulse.rise + delay, true});
      ++counters_.pulses_passed;
    }
    if (pulse.fall != kNever) {
      output.step.push_back(Edge{pulse.fall + delay, false});
      last_fall_ = std::max(last_fall_, pulse.fall);
    }
  }
  for (const SimTime start : glitches) {
    output.step.push_back(Edge{start + delay, true});
    output.step.push_back(Edge{start + settings_.glitch_width + delay, false});
    last_fall_ = std::max(last_fall_, start + settings_.glitch_width);
  }
  std::stable_sort(output.step.begin(), output.step.end(),
                   [](const Edge& a, const Edge& b) { return a.time < b.time; });
  output.dir.reserve(input.dir.size());
  for (const Edge& edge : input.dir) output.dir.push_back(Edge{edge.time + delay, edge.level});

  open_pulse_ = !shaped.empty() && shaped.back().fall == kNever;
  open_rise_ = open_pulse_ ? shaped.back().rise : 0;
  return output;
}

}  // namespace stepdance::sim
