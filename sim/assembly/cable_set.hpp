// The scenario's cables: each from one board's output port to another's input port, tapped by the
// VCD where it records that input, and what each counted.
#pragma once

#include <memory>
#include <vector>

#include <nlohmann/json.hpp>

#include "assembly/board_set.hpp"
#include "assembly/cable_link.hpp"
#include "assembly/pulse_delivery.hpp"
#include "assembly/recorders.hpp"
#include "scenario/scenario.hpp"

namespace stepdance::sim {

/// Owns the cables of one run (in scenario order) and the delivery of their pulses. Context:
/// host; build() before the run.
class CableSet {
 public:
  explicit CableSet(Scheduler& scheduler) : delivery_(scheduler) {}

  /// Lays each cable of `configs` between its boards in `boards`; `recorders` taps those whose
  /// input port the VCD records.
  void build(const std::vector<scenario::CableConfig>& configs, BoardSet& boards, const Recorders& recorders);
  const std::vector<std::unique_ptr<CableLink>>& links() const { return links_; }
  /// The summary's "cables" entry: each cable's ends and counters (`configs` as given to build()).
  nlohmann::json summary(const std::vector<scenario::CableConfig>& configs) const;
  /// Removes every cable (before the boards go).
  void clear() { links_.clear(); }

 private:
  PulseDelivery delivery_;
  std::vector<std::unique_ptr<CableLink>> links_;
};

}  // namespace stepdance::sim
