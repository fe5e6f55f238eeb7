// DeviceSet: each [[device]] through its kind's row, its probes and its pictures.
#include "assembly/device_set.hpp"

#include "assembly/board_plug.hpp"
#include "kinds/device_kind.hpp"

namespace stepdance::sim {

// Each [[device]] becomes its kind's model (its row in kinds/), plugged into its board.
void DeviceSet::build(const scenario::Scenario& scenario, BoardSet& boards, std::function<const Machine*()> machine) {
  for (const scenario::DeviceConfig& device : scenario.devices) {
    BoardPlug plug(*boards.slot(device.board).board, scenario.seed, machine);
    devices_[device.name] = device.kind->build(device, plug);
  }
}

const SimDevice* DeviceSet::find(const std::string& name) const {
  const auto found = devices_.find(name);
  return found == devices_.end() ? nullptr : found->second.get();
}

SimDevice* DeviceSet::find(const std::string& name) {
  const auto found = devices_.find(name);
  return found == devices_.end() ? nullptr : found->second.get();
}

void DeviceSet::add_probes(std::vector<CsvProbe>& probes) const {
  std::vector<DeviceProbe> device_probes;
  for (const auto& [name, device] : devices_) device->add_probes(name, device_probes);
  for (DeviceProbe& probe : device_probes) probes.push_back({{probe.column, probe.decimals}, std::move(probe.read)});
}

void DeviceSet::write_outputs(PictureSink& sink) {
  for (auto& [name, device] : devices_) device->write_outputs(name, sink);
}

}  // namespace stepdance::sim
