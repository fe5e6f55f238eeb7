// CableSet: cables laid between boards, and their counters for the summary.
#include "assembly/cable_set.hpp"

namespace stepdance::sim {

void CableSet::build(const std::vector<scenario::CableConfig>& configs, BoardSet& boards, const Recorders& recorders) {
  for (const scenario::CableConfig& config : configs) {
    const uint8_t to_port = static_cast<uint8_t>(config.to.port - 'A');
    links_.push_back(
        std::make_unique<CableLink>(config.settings, *boards.slot(config.to.board).board, to_port, delivery_));
    if (CableLink::Tap tap = recorders.input_tap(config.to.board, config.to.port))
      links_.back()->set_tap(std::move(tap));
    boards.slot(config.from.board)
        .board->wire(terminal::OutputPort{static_cast<uint8_t>(config.from.port - 'A')}, links_.back().get());
  }
}

nlohmann::json CableSet::summary(const std::vector<scenario::CableConfig>& configs) const {
  nlohmann::json cables = nlohmann::json::array();
  for (size_t i = 0; i < links_.size(); ++i) {
    const scenario::CableConfig& config = configs[i];
    const CableCounters& counters = links_[i]->counters();
    cables.push_back({{"from", config.from.board + ":OUT_" + config.from.port},
                      {"to", config.to.board + ":IN_" + config.to.port},
                      {"pulses_in", counters.pulses_in},
                      {"pulses_passed", counters.pulses_passed},
                      {"pulses_removed", counters.pulses_removed},
                      {"pulses_merged", counters.pulses_merged},
                      {"glitches_injected", counters.glitches_injected},
                      {"glitches_skipped", counters.glitches_skipped}});
  }
  return cables;
}

}  // namespace stepdance::sim
