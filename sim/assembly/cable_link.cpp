// Frame windows through the cable model; pulses out of it to the receiving board.
#include "assembly/cable_link.hpp"

#include "assembly/frame_waveform.hpp"
#include "stepdance/core/units.hpp"

namespace stepdance::sim {

CableLink::CableLink(const CableSettings& settings, SimBoard& receiver, uint8_t input_port, PulseDelivery& delivery)
    : cable_(settings), receiver_(receiver), input_port_(input_port), delivery_(delivery) {}

void CableLink::on_frame(SimTime start_ns, const protocol::FrameWords& words, SimTime frame_ns) {
  frame_waveform(start_ns, words, input_);
  const SimTime end_ns = start_ns + frame_ns;
  const PortWaveform output = cable_.transmit(input_, start_ns, end_ns);
  if (tap_) tap_(output);
  forward_pulses(output);
}

// Walks STEP edges in time order, applying every DIR edge at or before each one first (a DIR
// edge at the same ns as a STEP edge counts as already there, as in `stepdance decode`).
void CableLink::forward_pulses(const PortWaveform& output) {
  size_t next_dir = 0;
  auto dir_at = [&](SimTime time) {
    while (next_dir < output.dir.size() && output.dir[next_dir].time <= time) dir_level_ = output.dir[next_dir++].level;
    return dir_level_;
  };
  for (const Edge& edge : output.step) {
    if (edge.level) {
      pulse_open_ = true;
      open_pulse_.rise_ns = edge.time;
      open_pulse_.dir_at_rise = dir_at(edge.time);
      continue;
    }
    if (!pulse_open_) continue;
    pulse_open_ = false;
    open_pulse_.fall_ns = edge.time;
    open_pulse_.dir_at_fall = dir_at(edge.time);
    delivery_.send(receiver_, input_port_, open_pulse_);
    ++delivered_;
  }
  while (next_dir < output.dir.size()) dir_level_ = output.dir[next_dir++].level;
}

}  // namespace stepdance::sim
