// The host side of the boards' consoles: the scenario's scripted host clients, the timeline's
// serial input, and the clients' transcripts.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "assembly/board_set.hpp"
#include "assembly/host_client.hpp"
#include "kernel/scheduler/one_shot_pool.hpp"
#include "scenario/scenario.hpp"

namespace stepdance::sim {

/// Owns the host clients and the pending serial input of one run. Holds references to the
/// scenario and the boards (the Simulation owns them). Context: host; build() and
/// post_serial() before the run.
class HostSet {
 public:
  HostSet(Scheduler& scheduler, const scenario::Scenario& scenario, BoardSet& boards)
      : scheduler_(scheduler), scenario_(scenario), boards_(boards), serial_(scheduler, &send_serial, this) {}

  /// Starts a client for each [[host]] of the scenario on its board's console.
  void build();
  /// Sends the bytes of the timeline's serial action number `action_index` to its board's
  /// console at the action's time.
  void post_serial(size_t action_index) { serial_.post(scenario_.timeline[action_index].time, action_index); }
  /// The client on `board`, or null.
  const HostClient* client(const std::string& board) const;
  /// Writes each client's transcript the scenario asks for, at `path_of(configured name)`;
  /// appends the paths written to `files`.
  template <typename PathOf>
  void write_transcripts(PathOf path_of, std::vector<std::string>& files) const;
  /// Ends every client (before the boards go).
  void clear() { clients_.clear(); }

 private:
  static void send_serial(void* context, SimTime time, const size_t& action_index);
  const scenario::HostClientConfig* config_of(const HostClient& client) const;

  Scheduler& scheduler_;
  const scenario::Scenario& scenario_;
  BoardSet& boards_;
  OneShotPool<size_t> serial_;
  std::vector<std::unique_ptr<HostClient>> clients_;
};

template <typename PathOf>
void HostSet::write_transcripts(PathOf path_of, std::vector<std::string>& files) const {
  for (const auto& client : clients_) {
    const scenario::HostClientConfig* config = config_of(*client);
    if (config == nullptr || config->transcript.empty()) continue;
    const std::string path = path_of(config->transcript);
    client->write_transcript(path);
    files.push_back(path);
  }
}

}  // namespace stepdance::sim
