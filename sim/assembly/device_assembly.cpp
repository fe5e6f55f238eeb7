// Simulation assembly, part 2: input devices and their timeline, cables, VCD and CSV outputs.
#include <filesystem>

#include "kinds/device_kind.hpp"
#include "assembly/board_plug.hpp"
#include "assembly/csv_sampler.hpp"
#include "assembly/simulation.hpp"

namespace stepdance::sim {
namespace {

std::string port_key(const std::string& board, bool output, char port) {
  return board + (output ? ":OUT_" : ":IN_") + port;
}

}  // namespace

const FiveBarArm* Simulation::five_bar_arm(const std::string& name) const {
  const auto found = devices_.find(name);
  return found == devices_.end() ? nullptr : model_of<FiveBarArm>(found->second.get());
}

const SimDevice* Simulation::device(const std::string& name) const {
  const auto found = devices_.find(name);
  return found == devices_.end() ? nullptr : found->second.get();
}

void Simulation::write_device_outputs(SimulationReport& report) {
  const std::string directory = scenario_.output.directory;
  if (directory.empty() && !options_.output_directory) return;  // no output folder: no pictures
  PngPictureSink sink([this, &directory](const std::string& file) {
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

void Simulation::build_vcd() {
  if (vcd_path_.empty()) return;
  vcd_ = std::make_unique<VcdRecorder>(vcd_path_);
  vcd_->set_end_time(duration_);
  for (const scenario::PortLineRef& port : vcd_ports()) {
    const uint8_t index = static_cast<uint8_t>(port.port - 'A');
    if (port.output) {
      slot(port.board).board->add_wire_listener(index, vcd_->record_output(port.board, port.port));
    } else {
      vcd_inputs_[port_key(port.board, false, port.port)] = vcd_->declare_input(port.board, port.port);
    }
  }
}

void Simulation::build_cables() {
  for (const scenario::CableConfig& config : scenario_.cables) {
    const uint8_t to_port = static_cast<uint8_t>(config.to.port - 'A');
    cables_.push_back(std::make_unique<CableLink>(config.settings, *slot(config.to.board).board, to_port, delivery_));
    const auto tapped = vcd_inputs_.find(port_key(config.to.board, false, config.to.port));
    if (tapped != vcd_inputs_.end()) {
      VcdRecorder* recorder = vcd_.get();
      const size_t input = tapped->second;
      cables_.back()->set_tap([recorder, input](const PortWaveform& output) { recorder->record_input(input, output); });
    }
    slot(config.from.board).board->add_wire_listener(static_cast<uint8_t>(config.from.port - 'A'), cables_.back().get());
  }
}

// Columns: the pen (with a machine), every socket's model, then each device's own (knob counts,
// pot readings, ...).
void Simulation::build_csv() {
  const std::string& path = csv_path_;
  if (path.empty()) return;
  std::vector<CsvProbe> probes;
  if (machine_) {
    const Machine* machine = machine_.get();
    probes.push_back({{"pen_x_mm", 3}, [machine](SimTime) { return machine->pen_position().x_mm; }});
    probes.push_back({{"pen_y_mm", 3}, [machine](SimTime) { return machine->pen_position().y_mm; }});
    probes.push_back({{"pen_down", 0}, [machine](SimTime) { return machine->pen_down() ? 1.0 : 0.0; }});
  }
  for (const BoardSlot& slot : boards_) {
    for (uint8_t port = 0; port < 4; ++port) {
      const std::string prefix = slot.config->name + "." + static_cast<char>('A' + port);
      if (const StepperDriver* stepper = slot.sockets[port].stepper.get()) {
        probes.push_back({{prefix + "_steps", 0}, [stepper](SimTime) { return static_cast<double>(stepper->position_steps()); }});
      }
      if (const ServoBoard* servo = slot.sockets[port].servo.get()) {
        probes.push_back({{prefix + "_servo_steps", 0}, [servo](SimTime) { return static_cast<double>(servo->position_steps()); }});
      }
    }
  }
  std::vector<DeviceProbe> device_probes;
  for (const auto& [name, device] : devices_) device->add_probes(name, device_probes);
  for (DeviceProbe& probe : device_probes) probes.push_back({{probe.column, probe.decimals}, std::move(probe.read)});
  const SimTime interval = static_cast<SimTime>(scenario_.output.csv_interval_ms * 1e6 + 0.5);
  csv_ = std::make_unique<CsvSampler>(scheduler_, path, std::move(probes), interval);
}

}  // namespace stepdance::sim
