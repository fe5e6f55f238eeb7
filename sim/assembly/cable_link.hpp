// A TRRS cable in a running simulation: an output port's frames through the Cable model to an input port.
#pragma once

#include <cstdint>
#include <functional>

#include "assembly/pulse_delivery.hpp"
#include "board/host/sim_board.hpp"
#include "board/host/wire.hpp"
#include "common/edges.hpp"
#include "models/cable.hpp"

namespace stepdance::sim {

/// Listens to the sending board's output port. Every frame window [start, start + 40 µs) goes
/// through the Cable model (delay, stretch, glitches); each STEP pulse that comes out is sent to
/// the receiving board's input port, to be captured at its falling edge with the DIR levels at
/// both of its edges. Pulses may span windows (a stretched pulse ending after the window).
class CableLink final : public WireListener {
 public:
  /// Called with each window's output waveform (for the VCD of the input port's lines).
  using Tap = std::function<void(const PortWaveform& output)>;

  CableLink(const CableSettings& settings, SimBoard& receiver, uint8_t input_port, PulseDelivery& delivery);

  /// Glitches happen between frames too, so a glitching cable sees every window.
  bool wants_idle_frames() const override { return cable_.settings().glitch_every > 0; }
  void on_frame(SimTime start_ns, const protocol::FrameWords& words, SimTime frame_ns) override;
  void set_tap(Tap tap) { tap_ = std::move(tap); }

  /// What the cable model counted (pulses in, passed, removed, merged, glitches).
  const CableCounters& counters() const { return cable_.counters(); }
  /// Pulses handed to the receiving board (real ones and glitches).
  uint64_t pulses_sent_on() const { return delivered_; }

 private:
  void forward_pulses(const PortWaveform& output);

  Cable cable_;
  SimBoard& receiver_;
  uint8_t input_port_;
  PulseDelivery& delivery_;
  Tap tap_;
  PortWaveform input_;
  bool dir_level_ = false;  ///< cable-output DIR level before the current window's edges
  bool pulse_open_ = false;
  ArrivingPulse open_pulse_;
  uint64_t delivered_ = 0;
};

}  // namespace stepdance::sim
