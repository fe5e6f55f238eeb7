// Simulation assembly: the machine (its kind's row in kinds/ builds it from the socket models)
// and when it is re-read as the motors step.
#include <algorithm>

#include "assembly/simulation.hpp"
#include "kinds/machine_kind.hpp"
#include "stepdance/protocol/signals.hpp"

namespace stepdance::sim {
namespace {

/// The machine is re-read at least every this many frames even when no motor stepped, so the
/// pen follows the servo board (whose pulse changes every 24.85 ms).
constexpr uint32_t kIdleFramesPerMachineUpdate = 25;
/// A frame's last possible edge, after its start.
constexpr SimTime kFrameWireNs = SimTime{protocol::kFrameBitsUs} * kMicrosecond;

}  // namespace

bool Simulation::build_machine(SimulationError& error) {
  if (!scenario_.machine) return true;
  const scenario::MachineConfig& config = *scenario_.machine;
  BoardSlot& owner = slot(config.board);
  const SocketModels sockets{[&owner](char port) { return owner.sockets[port - 'A'].stepper.get(); },
                             [&owner](char port) { return owner.sockets[port - 'A'].servo.get(); }};
  PenTraceSettings trace;
  trace.record_pen_up = scenario_.output.pen_up_travel;
  machine_ = config.kind->build(config, sockets, trace);
  if (!machine_) {
    error = {SimulationError::kBadInput, place(config.line) + "the machine's motor sockets must hold steppers"};
    return false;
  }
  owner.board->on_frames_played([this](SimTime time) { after_frames(time); });
  return true;
}

void Simulation::after_frames(SimTime frame_start_ns) {
  ++ticks_since_machine_update_;
  if (!machine_moved_ && ticks_since_machine_update_ < kIdleFramesPerMachineUpdate) return;
  update_machine(frame_start_ns + kFrameWireNs);
}

void Simulation::update_machine(SimTime time_ns) {
  machine_time_ns_ = std::max(machine_time_ns_, time_ns);
  machine_->update(machine_time_ns_);
  machine_moved_ = false;
  ticks_since_machine_update_ = 0;
}

}  // namespace stepdance::sim
