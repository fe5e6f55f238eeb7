// Lookups on the scenario structs and the diagnostic's text form.
#include "scenario/scenario.hpp"

#include "scenario/diagnostic.hpp"

namespace stepdance::sim::scenario {

std::string Diagnostic::to_string() const {
  return line > 0 ? file + ":" + std::to_string(line) + ": " + message : file + ": " + message;
}

const SocketConfig* BoardConfig::socket(char port) const {
  for (const SocketConfig& candidate : sockets) {
    if (candidate.port == port) return &candidate;
  }
  return nullptr;
}

const BoardConfig* Scenario::board(std::string_view name) const {
  for (const BoardConfig& candidate : boards) {
    if (candidate.name == name) return &candidate;
  }
  return nullptr;
}

const DeviceConfig* Scenario::device(std::string_view name) const {
  for (const DeviceConfig& candidate : devices) {
    if (candidate.name == name) return &candidate;
  }
  return nullptr;
}

}  // namespace stepdance::sim::scenario
