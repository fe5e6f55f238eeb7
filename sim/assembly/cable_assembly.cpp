// Simulation assembly: cables from one board's output port to another's input port, tapped by
// the VCD where it records that input.
#include "assembly/simulation.hpp"

namespace stepdance::sim {

void Simulation::build_cables() {
  for (const scenario::CableConfig& config : scenario_.cables) {
    const uint8_t to_port = static_cast<uint8_t>(config.to.port - 'A');
    cables_.push_back(std::make_unique<CableLink>(config.settings, *slot(config.to.board).board, to_port, delivery_));
    const auto tapped = vcd_inputs_.find(vcd_input_key(config.to.board, config.to.port));
    if (tapped != vcd_inputs_.end()) {
      VcdRecorder* recorder = vcd_.get();
      const size_t input = tapped->second;
      cables_.back()->set_tap([recorder, input](const PortWaveform& output) { recorder->record_input(input, output); });
    }
    slot(config.from.board).board->add_wire_listener(static_cast<uint8_t>(config.from.port - 'A'), cables_.back().get());
  }
}

}  // namespace stepdance::sim
