// The scenario's [[device]] entries, each built by its kind's row (kinds/) and plugged into its
// board; their timeline actions, CSV columns and end-of-run pictures.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "assembly/board_set.hpp"
#include "assembly/csv_sampler.hpp"
#include "kinds/sim_device.hpp"
#include "scenario/scenario.hpp"

namespace stepdance::sim {

/// Owns every device by name, whatever its kind. Context: host; build() before the run.
class DeviceSet {
 public:
  /// Builds each device of `scenario` through its kind's row, plugged into its board in
  /// `boards`; `machine` gives the machine a device may watch (called when the device asks).
  void build(const scenario::Scenario& scenario, BoardSet& boards, std::function<const Machine*()> machine);
  /// The device named `name`, or null.
  const SimDevice* find(const std::string& name) const;
  SimDevice* find(const std::string& name);
  /// Hands a device action of the timeline to its device (which schedules it).
  void schedule(const scenario::Action& action) { devices_.at(action.target)->schedule(action); }
  /// Each device's own CSV columns (knob counts, pot readings, …), devices in name order.
  void add_probes(std::vector<CsvProbe>& probes) const;
  /// Each device's pictures at the end of the run, through `sink`.
  void write_outputs(PictureSink& sink);

 private:
  std::map<std::string, std::unique_ptr<SimDevice>> devices_;
};

}  // namespace stepdance::sim
