// A board's four ports as the wire sees them: the frames an output port plays to its listeners
// (counted as sent), and the pulses that reach an input port (decoded and counted as received).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "board/host/frame_pulses.hpp"
#include "board/host/wire.hpp"
#include "common/sim_time.hpp"
#include "output/pulse_counts.hpp"
#include "stepdance/protocol/pulse_decoder.hpp"

namespace stepdance::sim {

/// The port state of one board. Ports are numbered 0–3 (A–D). Context: host, on the
/// simulation's thread; the sketch's port calls arrive through SimBoard.
class BoardPorts {
 public:
  static constexpr uint8_t kPorts = 4;

  // ---- wiring ----
  /// Adds a listener of output port `port`'s wire (not owned). One that wants idle frames also
  /// hears every frame tick without pulses.
  void add_listener(uint8_t port, WireListener* listener);

  // ---- the program side ----
  /// The sketch claims output port `port`; false if it was claimed already.
  bool claim_output(uint8_t port);
  /// The words the sketch handed over for `port`'s next frame (idle words need no playing).
  void queue_frame(uint8_t port, const protocol::FrameWords& words);
  /// The sketch begins input port `port`, sampling DIR at `edge`.
  void begin_input(uint8_t port, protocol::DirSampleEdge edge);
  /// Every input port begun (a firmware image drives and captures through its own peripherals).
  void begin_all_inputs();
  /// Plays every queued frame from `start_ns` (the frame tick), frames `frame_ns` apart, and
  /// idle frames to the listeners that want them; pulses falling after `end_ns` are not counted.
  void play_queued(SimTime start_ns, SimTime frame_ns, SimTime end_ns);
  /// Output port `port` plays `words` from `start_ns` (a firmware's frame clock), claiming it.
  void play(uint8_t port, SimTime start_ns, const protocol::FrameWords& words, SimTime frame_ns, SimTime end_ns);
  /// A STEP pulse reaches input port `port`: counted and returned as the capture timer saw it, or
  /// nothing (counted as unclaimed) when no input port was begun there.
  std::optional<protocol::CapturedPulse> capture(uint8_t port, const ArrivingPulse& pulse);

  // ---- observation ----
  /// Pulses played on output port `port` (decoded from the wire).
  const PulseCounts& sent(uint8_t port) const { return ports_[port].sent; }
  /// Pulses that reached input port `port`, decoded as the port's mode does (STEP_DIR-mode
  /// steps are tallied under SIGNAL_X: the host cannot see which signal the sketch chose).
  const PulseCounts& received(uint8_t port) const { return ports_[port].received; }
  /// Pulses that reached an input port no InputPort had begun (they went nowhere).
  uint64_t unclaimed_pulses(uint8_t port) const { return ports_[port].unclaimed; }
  bool output_claimed(uint8_t port) const { return ports_[port].output_claimed; }
  bool input_begun(uint8_t port) const { return ports_[port].input_begun; }

 private:
  struct PortState {
    bool output_claimed = false;
    bool frame_pending = false;
    protocol::FrameWords pending{};
    std::vector<WireListener*> listeners;
    std::vector<WireListener*> idle_listeners;  ///< the subset that also wants idle frames
    PulseCounts sent;
    bool input_begun = false;
    protocol::DirSampleEdge edge = protocol::DirSampleEdge::kFalling;
    PulseCounts received;
    uint64_t unclaimed = 0;
  };
  void play_words(PortState& port, SimTime start_ns, const protocol::FrameWords& words, SimTime frame_ns,
                  SimTime end_ns);

  std::array<PortState, kPorts> ports_{};
  uint8_t pending_ports_ = 0;         ///< bit p: port p has a frame to play at the next tick
  uint8_t idle_listening_ports_ = 0;  ///< bit p: port p has listeners that want idle frames
};

}  // namespace stepdance::sim
