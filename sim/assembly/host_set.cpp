// HostSet: the scripted clients, the timeline's serial input and whose transcript is whose.
#include "assembly/host_set.hpp"

namespace stepdance::sim {

void HostSet::build() {
  for (const scenario::HostClientConfig& config : scenario_.hosts) {
    clients_.push_back(std::make_unique<HostClient>(config, *boards_.slot(config.board).board, scheduler_));
    clients_.back()->start();
  }
}

const HostClient* HostSet::client(const std::string& board) const {
  for (const auto& client : clients_) {
    if (client->board_name() == board) return client.get();
  }
  return nullptr;
}

void HostSet::send_serial(void* context, SimTime, const size_t& action_index) {
  auto& hosts = *static_cast<HostSet*>(context);
  const scenario::Action& action = hosts.scenario_.timeline[action_index];
  hosts.boards_.slot(action.target).board->console().send(action.serial_bytes);
}

// The [[host]] entry of the client's board (the last one that names it).
const scenario::HostClientConfig* HostSet::config_of(const HostClient& client) const {
  const scenario::HostClientConfig* config = nullptr;
  for (const auto& candidate : scenario_.hosts) {
    if (candidate.board == client.board_name()) config = &candidate;
  }
  return config;
}

}  // namespace stepdance::sim
