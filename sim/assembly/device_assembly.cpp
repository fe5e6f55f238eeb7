// Simulation assembly: each [[device]] through its kind's row, the timeline's device actions,
// and the pictures devices leave at the end.
#include <filesystem>

#include "kinds/device_kind.hpp"
#include "assembly/board_plug.hpp"
#include "assembly/simulation.hpp"

namespace stepdance::sim {
const SimDevice* Simulation::device(const std::string& name) const {
  const auto found = devices_.find(name);
  return found == devices_.end() ? nullptr : found->second.get();
}

SimDevice* Simulation::device(const std::string& name) {
  const auto found = devices_.find(name);
  return found == devices_.end() ? nullptr : found->second.get();
}

void Simulation::write_device_outputs(SimulationReport& report) {
  const std::string directory = scenario_.output.directory;
  if (directory.empty() && !options_.output_directory) return;  // no output folder: no pictures
  if (!options_.pictures) return;                                // no picture writer
  PictureFileSink sink(*options_.pictures, [this, &directory](const std::string& file) {
    return output_path((std::filesystem::path(directory) / file).string());
  }, report.files);
  for (auto& [name, device] : devices_) device->write_outputs(name, sink);
}

// Each [[device]] becomes its kind's model (its row in kinds/), plugged into its board.
void Simulation::build_devices() {
  for (const scenario::DeviceConfig& device : scenario_.devices) {
    BoardPlug plug(*slot(device.board).board, scenario_.seed, [this] { return machine_.get(); });
    devices_[device.name] = device.kind->build(device, plug);
  }
}

// Device schedules are known in advance and go straight into the models; serial input needs
// an event at its time.
void Simulation::apply_timeline() {
  for (size_t index = 0; index < scenario_.timeline.size(); ++index) {
    const scenario::Action& action = scenario_.timeline[index];
    if (action.type == scenario::ActionType::kSerial) {
      serial_actions_.post(action.time, index);
    } else {
      devices_.at(action.target)->schedule(action);
    }
  }
}

}  // namespace stepdance::sim
