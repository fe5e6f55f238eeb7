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

/// Pairs the STEP edges into pulses, continuing a pulse left open by the previous window (high
/// since `open_rise`, its rise already sent).
std::vector<Pulse> pair_edges(const std::vector<Edge>& step, bool open_pulse, SimTime open_rise,
                              CableCounters& counters) {
  std::vector<Pulse> pulses;
  bool high = open_pulse;
  Pulse current{open_rise, kNever, open_pulse};
  for (const Edge& edge : step) {
    if (edge.level == high) continue;
    high = edge.level;
    if (high) {
      current = Pulse{edge.time, kNever, false};
      ++counters.pulses_in;
    } else {
      current.fall = edge.time;
      pulses.push_back(current);
    }
  }
  if (high) pulses.push_back(current);
  return pulses;
}

/// Stretches the pulses, then merges pulses that now touch (none starts before `last_fall`).
std::vector<Pulse> stretch_and_merge(const std::vector<Pulse>& pulses, SimTime stretch, SimTime window_start,
                                     SimTime last_fall, CableCounters& counters) {
  std::vector<Pulse> shaped;
  for (Pulse pulse : pulses) {
    if (pulse.fall != kNever) {
      pulse.fall += stretch;
      if (pulse.rise_sent) {
        // Its rising edge went out with an earlier window: the fall cannot move before this one.
        pulse.fall = std::max({pulse.fall, pulse.rise + 1, window_start});
      } else if (pulse.fall <= pulse.rise) {
        ++counters.pulses_removed;
        continue;
      }
    }
    if (!pulse.rise_sent && pulse.rise <= last_fall) pulse.rise = last_fall + 1;
    if (!shaped.empty() && pulse.rise <= shaped.back().fall) {
      shaped.back().fall = std::max(shaped.back().fall, pulse.fall);
      ++counters.pulses_merged;
      continue;
    }
    if (pulse.fall != kNever && pulse.fall <= pulse.rise) pulse.fall = pulse.rise + 1;
    shaped.push_back(pulse);
  }
  return shaped;
}

/// Glitch slots of [window_start, window_end) whose pulse fits in the window and touches no real
/// pulse (nor `last_fall`).
std::vector<SimTime> glitch_starts(const CableSettings& settings, const std::vector<Pulse>& shaped,
                                   SimTime window_start, SimTime window_end, SimTime last_fall,
                                   CableCounters& counters) {
  std::vector<SimTime> glitches;
  if (settings.glitch_every <= 0 || settings.glitch_width <= 0) return glitches;
  SimTime slot = std::max<SimTime>(1, (window_start + settings.glitch_every - 1) / settings.glitch_every);
  for (SimTime start = slot * settings.glitch_every; start < window_end; start = (++slot) * settings.glitch_every) {
    const SimTime end = start + settings.glitch_width;
    const bool clear = end < window_end && start > last_fall &&
                       std::none_of(shaped.begin(), shaped.end(),
                                    [&](const Pulse& pulse) { return !(end < pulse.rise || start > pulse.fall); });
    if (clear) {
      glitches.push_back(start);
      ++counters.glitches_injected;
    } else {
      ++counters.glitches_skipped;
    }
  }
  return glitches;
}

/// The shaped pulses and the glitches as edges, delayed, sorted; `last_fall` follows the falls sent.
PortWaveform emit(const std::vector<Pulse>& shaped, const std::vector<SimTime>& glitches, const CableSettings& settings,
                  SimTime& last_fall, CableCounters& counters) {
  PortWaveform output;
  const SimTime delay = settings.delay;
  for (const Pulse& pulse : shaped) {
    if (!pulse.rise_sent) {
      output.step.push_back(Edge{pulse.rise + delay, true});
      ++counters.pulses_passed;
    }
    if (pulse.fall != kNever) {
      output.step.push_back(Edge{pulse.fall + delay, false});
      last_fall = std::max(last_fall, pulse.fall);
    }
  }
  for (const SimTime start : glitches) {
    output.step.push_back(Edge{start + delay, true});
    output.step.push_back(Edge{start + settings.glitch_width + delay, false});
    last_fall = std::max(last_fall, start + settings.glitch_width);
  }
  std::stable_sort(output.step.begin(), output.step.end(),
                   [](const Edge& a, const Edge& b) { return a.time < b.time; });
  return output;
}

}  // namespace

Cable::Cable(const CableSettings& settings) : settings_(settings) {}

PortWaveform Cable::transmit(const PortWaveform& input, SimTime window_start, SimTime window_end) {
  const std::vector<Pulse> pulses = pair_edges(input.step, open_pulse_, open_rise_, counters_);
  const std::vector<Pulse> shaped = stretch_and_merge(pulses, settings_.stretch, window_start, last_fall_, counters_);
  const std::vector<SimTime> glitches =
      glitch_starts(settings_, shaped, window_start, window_end, last_fall_, counters_);
  PortWaveform output = emit(shaped, glitches, settings_, last_fall_, counters_);
  output.dir.reserve(input.dir.size());
  for (const Edge& edge : input.dir) output.dir.push_back(Edge{edge.time + settings_.delay, edge.level});
  open_pulse_ = !shaped.empty() && shaped.back().fall == kNever;
  open_rise_ = open_pulse_ ? shaped.back().rise : 0;
  return output;
}

}  // namespace stepdance::sim
