// Simulation assembly, the recorders: the VCD (every output port it records, and the cabled
// input ports through their cables' taps) and the CSV sampler's columns.
#include "assembly/csv_sampler.hpp"
#include "assembly/simulation.hpp"
#include "scenario/names.hpp"

namespace stepdance::sim {

std::string Simulation::vcd_input_key(const std::string& board, char port) { return board + ":IN_" + port; }

void Simulation::build_vcd() {
  if (vcd_path_.empty()) return;
  vcd_ = std::make_unique<VcdRecorder>(vcd_path_);
  vcd_->set_end_time(duration_);
  for (const scenario::PortLineRef& port : vcd_ports()) {
    const uint8_t index = static_cast<uint8_t>(port.port - 'A');
    if (port.output) {
      slot(port.board).board->add_wire_listener(index, vcd_->record_output(port.board, port.port));
    } else {
      vcd_inputs_[vcd_input_key(port.board, port.port)] = vcd_->declare_input(port.board, port.port);
    }
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

std::vector<scenario::PortLineRef> Simulation::vcd_ports() const {
  if (!scenario_.output.vcd_ports.empty() || !options_.vcd_file) return scenario_.output.vcd_ports;
  std::vector<scenario::PortLineRef> ports;
  for (const scenario::BoardConfig& board : scenario_.boards) {
    for (char port = 'A'; port <= 'D'; ++port) {
      if (scenario::module_has_output_port(*board.module, port)) ports.push_back({board.name, true, port});
    }
  }
  for (const scenario::CableConfig& cable : scenario_.cables) ports.push_back({cable.to.board, false, cable.to.port});
  return ports;
}

}  // namespace stepdance::sim
