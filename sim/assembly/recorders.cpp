// Recorders: the VCD's ports and taps, the CSV's columns.
#include "assembly/recorders.hpp"

namespace stepdance::sim {
namespace {

/// The key of a recorded input port: "board:IN_A".
std::string vcd_input_key(const std::string& board, char port) { return board + ":IN_" + port; }

/// The CSV columns of every socket's model: board.A_steps, board.B_servo_steps, …
void add_socket_probes(const BoardSet& boards, std::vector<CsvProbe>& probes) {
  for (const BoardSlot& slot : boards.slots()) {
    for (uint8_t port = 0; port < 4; ++port) {
      const std::string prefix = slot.config->name + "." + static_cast<char>('A' + port);
      if (const StepperDriver* stepper = slot.sockets[port].stepper.get()) {
        probes.push_back(
            {{prefix + "_steps", 0}, [stepper](SimTime) { return static_cast<double>(stepper->position_steps()); }});
      }
      if (const ServoBoard* servo = slot.sockets[port].servo.get()) {
        probes.push_back(
            {{prefix + "_servo_steps", 0}, [servo](SimTime) { return static_cast<double>(servo->position_steps()); }});
      }
    }
  }
}

}  // namespace

void Recorders::build_vcd(const std::string& path, const std::vector<scenario::PortLineRef>& ports, SimTime end_ns,
                          BoardSet& boards) {
  if (path.empty()) return;
  vcd_path_ = path;
  vcd_ = std::make_unique<VcdRecorder>(path);
  vcd_->set_end_time(end_ns);
  for (const scenario::PortLineRef& port : ports) {
    const uint8_t index = static_cast<uint8_t>(port.port - 'A');
    if (port.output) {
      boards.slot(port.board).board->wire(terminal::OutputPort{index}, vcd_->record_output(port.board, port.port));
    } else {
      vcd_inputs_[vcd_input_key(port.board, port.port)] = vcd_->declare_input(port.board, port.port);
    }
  }
}

CableLink::Tap Recorders::input_tap(const std::string& board, char port) const {
  const auto tapped = vcd_inputs_.find(vcd_input_key(board, port));
  if (tapped == vcd_inputs_.end()) return {};
  VcdRecorder* recorder = vcd_.get();
  const size_t input = tapped->second;
  return [recorder, input](const PortWaveform& output) { recorder->record_input(input, output); };
}

void Recorders::build_csv(const std::string& path, double interval_ms, const Machine* machine, const BoardSet& boards,
                          const DeviceSet& devices) {
  if (path.empty()) return;
  csv_path_ = path;
  std::vector<CsvProbe> probes;
  if (machine != nullptr) {
    probes.push_back({{"pen_x_mm", 3}, [machine](SimTime) { return machine->pen_position().x_mm; }});
    probes.push_back({{"pen_y_mm", 3}, [machine](SimTime) { return machine->pen_position().y_mm; }});
    probes.push_back({{"pen_down", 0}, [machine](SimTime) { return machine->pen_down() ? 1.0 : 0.0; }});
  }
  add_socket_probes(boards, probes);
  devices.add_probes(probes);
  const SimTime interval = static_cast<SimTime>(interval_ms * 1e6 + 0.5);
  csv_ = std::make_unique<CsvSampler>(scheduler_, path, std::move(probes), interval);
}

void Recorders::close(SimTime end_ns, std::vector<std::string>& files) {
  if (vcd_) {
    vcd_->close(end_ns);
    files.push_back(vcd_path_);
  }
  if (csv_) {
    csv_->close();
    files.push_back(csv_path_);
  }
}

}  // namespace stepdance::sim
