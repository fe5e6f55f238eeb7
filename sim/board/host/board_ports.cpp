// BoardPorts: frames played to the listeners, pulses captured and decoded.
#include "board/host/board_ports.hpp"

namespace stepdance::sim {
namespace {

/// Capture timer: 150 ticks per µs into a 16-bit counter.
constexpr int64_t kCaptureTicksPerUs = 150;

// The capture counter at a time, unwrapped: ticks rounded half up (as `stepdance decode` converts
// edges). The board's 16-bit counter is this modulo 2^16; captured_from_ticks keeps the overflow
// count, as the Teensy backend does by counting counter reloads.
uint64_t capture_ticks(SimTime time_ns) { return static_cast<uint64_t>((time_ns * kCaptureTicksPerUs + 500) / 1000); }

}  // namespace

void BoardPorts::add_listener(uint8_t port, WireListener* listener) {
  PortState& state = ports_.at(port);
  state.listeners.push_back(listener);
  if (!listener->wants_idle_frames()) return;
  state.idle_listeners.push_back(listener);
  idle_listening_ports_ = static_cast<uint8_t>(idle_listening_ports_ | (1u << port));
}

bool BoardPorts::claim_output(uint8_t port) {
  PortState& state = ports_.at(port);
  if (state.output_claimed) return false;
  state.output_claimed = true;
  return true;
}

void BoardPorts::queue_frame(uint8_t port, const protocol::FrameWords& words) {
  PortState& state = ports_.at(port);
  state.pending = words;
  state.frame_pending = (words.step_bits | words.dir_bits) != 0;  // idle frames need no playing
  if (state.frame_pending) pending_ports_ = static_cast<uint8_t>(pending_ports_ | (1u << port));
}

void BoardPorts::begin_input(uint8_t port, protocol::DirSampleEdge edge) {
  PortState& state = ports_.at(port);
  state.input_begun = true;
  state.edge = edge;
}

void BoardPorts::begin_all_inputs() {
  for (PortState& port : ports_) port.input_begun = true;
}

// The words handed over during the previous frame go on the wire now, at the fixed phase.
void BoardPorts::play_queued(SimTime start_ns, SimTime frame_ns, SimTime end_ns) {
  if ((pending_ports_ | idle_listening_ports_) == 0) return;
  for (PortState& port : ports_) {
    if (!port.frame_pending) {
      for (WireListener* listener : port.idle_listeners) listener->on_frame(start_ns, protocol::FrameWords{}, frame_ns);
      continue;
    }
    port.frame_pending = false;
    play_words(port, start_ns, port.pending, frame_ns, end_ns);
  }
  pending_ports_ = 0;
}

void BoardPorts::play(uint8_t port, SimTime start_ns, const protocol::FrameWords& words, SimTime frame_ns,
                      SimTime end_ns) {
  PortState& state = ports_.at(port);
  state.output_claimed = true;
  if ((words.step_bits | words.dir_bits) == 0) {
    for (WireListener* listener : state.idle_listeners) listener->on_frame(start_ns, words, frame_ns);
    return;
  }
  play_words(state, start_ns, words, frame_ns, end_ns);
}

// Counts the frame's pulses as sent (those ending after the run's end are cut off) and hands the
// frame to every listener of the port.
void BoardPorts::play_words(PortState& port, SimTime start_ns, const protocol::FrameWords& words, SimTime frame_ns,
                            SimTime end_ns) {
  const SimTime frame_end_ns = start_ns + SimTime{protocol::kFrameBitsUs} * kMicrosecond;
  if (frame_end_ns <= end_ns) {
    count_frame_pulses(words, port.sent);
  } else {
    count_frame_pulses(words, port.sent, (end_ns - start_ns) / kMicrosecond);
  }
  for (WireListener* listener : port.listeners) listener->on_frame(start_ns, words, frame_ns);
}

// The capture timer's view of the pulse: DIR at the edge the port samples, the mode that edge
// means (rising: a STEP/DIR driver's input; falling: a Stepdance port).
std::optional<protocol::CapturedPulse> BoardPorts::capture(uint8_t port, const ArrivingPulse& pulse) {
  PortState& state = ports_.at(port);
  if (!state.input_begun) {
    ++state.unclaimed;
    return std::nullopt;
  }
  const bool at_rising = state.edge == protocol::DirSampleEdge::kRising;
  const protocol::CapturedPulse captured =
      protocol::captured_from_ticks(capture_ticks(pulse.rise_ns), capture_ticks(pulse.fall_ns),
                                    at_rising ? pulse.dir_at_rise : pulse.dir_at_fall, protocol::CaptureClock{});
  const InputMode mode = at_rising ? INPUT_MODE_STEP_DIR : INPUT_MODE_STEPDANCE;
  state.received.add(protocol::decode_pulse(captured, protocol::CaptureClock{}, mode, SIGNAL_X));
  return captured;
}

}  // namespace stepdance::sim
