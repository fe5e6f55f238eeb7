// Simulation assembly: scripted host clients on the boards' consoles, the timeline's serial
// input, and the clients' transcripts.
#include "assembly/simulation.hpp"

namespace stepdance::sim {

void Simulation::build_hosts() {
  for (const scenario::HostClientConfig& config : scenario_.hosts) {
    hosts_.push_back(std::make_unique<HostClient>(config, *slot(config.board).board, scheduler_));
    hosts_.back()->start();
  }
}

const HostClient* Simulation::host_client(const std::string& board) const {
  for (const auto& host : hosts_) {
    if (host->board_name() == board) return host.get();
  }
  return nullptr;
}

void Simulation::on_serial_action(void* context, SimTime, const size_t& action_index) {
  auto& simulation = *static_cast<Simulation*>(context);
  const scenario::Action& action = simulation.scenario_.timeline[action_index];
  simulation.slot(action.target).board->send_console(action.serial_bytes);
}

void Simulation::write_transcripts(SimulationReport& report) const {
  for (const auto& host : hosts_) {
    const scenario::HostClientConfig* config = nullptr;
    for (const auto& candidate : scenario_.hosts) {
      if (candidate.board == host->board_name()) config = &candidate;
    }
    if (config == nullptr || config->transcript.empty()) continue;
    const std::string path = output_path(config->transcript);
    host->write_transcript(path);
    report.files.push_back(path);
  }
}

}  // namespace stepdance::sim
