// Simulation assembly, part 2: input devices and their timeline, cables, VCD and CSV outputs.
#include <filesystem>
#include <map>

#include "models/random_stream.hpp"
#include "wiring/csv_sampler.hpp"
#include "wiring/simulation.hpp"

namespace stepdance::sim {
namespace {

using scenario::Connector;

/// Index of a connector within its group (ENC1 → 0, A3 → 2, D2 → 1, LIMIT_C → 2).
uint8_t connector_index(Connector connector) {
  switch (connector) {
    case Connector::kEnc1: case Connector::kA1: case Connector::kD1: case Connector::kLimitA: return 0;
    case Connector::kEnc2: case Connector::kA2: case Connector::kD2: case Connector::kLimitB: return 1;
    case Connector::kA3: case Connector::kLimitC: return 2;
    case Connector::kA4: case Connector::kLimitD: return 3;
  }
  return 0;
}

bool is_analog_connector(Connector connector) {
  return connector == Connector::kA1 || connector == Connector::kA2 || connector == Connector::kA3 ||
         connector == Connector::kA4;
}

/// The board pin behind a digital or analog connector.
uint8_t connector_pin(const BoardDefinition& board, Connector connector) {
  const uint8_t index = connector_index(connector);
  if (is_analog_connector(connector)) return board.io_a[index];
  if (connector == Connector::kD1 || connector == Connector::kD2) return board.io_d[index];
  return board.output_ports[index].limit;
}

MachineAxis machine_axis(scenario::LimitAxis axis) {
  if (axis == scenario::LimitAxis::kY) return MachineAxis::kY;
  return axis == scenario::LimitAxis::kZ ? MachineAxis::kZ : MachineAxis::kX;
}

std::string port_key(const std::string& board, bool output, char port) {
  return board + (output ? ":OUT_" : ":IN_") + port;
}

}  // namespace

const FiveBarArm* Simulation::five_bar_arm(const std::string& name) const {
  const auto found = arms_.find(name);
  return found == arms_.end() ? nullptr : found->second.get();
}

void Simulation::build_devices() {
  for (const scenario::DeviceConfig& device : scenario_.devices) build_device(device, slot(device.board));
}

void Simulation::build_device(const scenario::DeviceConfig& device, BoardSlot& slot) {
  SimBoard& board = *slot.board;
  const BoardDefinition& definition = board.definition();
  switch (device.type) {
    case scenario::DeviceType::kEncoder: {
      auto& encoder = encoders_[device.name] = std::make_unique<QuadratureEncoder>(device.pulses_per_revolution, device.start_count);
      const QuadratureEncoder* model = encoder.get();
      board.connect_encoder(connector_index(device.connector), [model](SimTime time) { return model->count_at(time); });
      break;
    }
    case scenario::DeviceType::kPendulum: {
      PendulumSettings settings;
      settings.pulses_per_revolution = device.pulses_per_revolution;
      settings.amplitude_deg = device.amplitude_deg;
      settings.period_s = device.period_s;
      settings.decay_s = device.decay_s;
      settings.release = from_seconds(device.release_s);
      auto& pendulum = pendulums_[device.name] = std::make_unique<DampedPendulum>(settings);
      const DampedPendulum* model = pendulum.get();
      board.connect_encoder(connector_index(device.connector), [model](SimTime time) { return model->count_at(time); });
      break;
    }
    case scenario::DeviceType::kFiveBarArm: {
      FiveBarArmSettings settings;
      settings.pulses_per_revolution = device.pulses_per_revolution;
      for (const auto& [x, y] : device.path_mm) settings.path_mm.push_back(PenPoint{x, y});
      settings.dwell_s = device.dwell_s;
      settings.speed_mm_per_s = device.speed_mm_per_s;
      settings.start = from_seconds(device.start_s);
      auto& arm = arms_[device.name] = std::make_unique<FiveBarArm>(settings);
      const FiveBarArm* model = arm.get();
      board.connect_encoder(connector_index(device.connector), [model](SimTime time) { return model->right_count_at(time); });
      board.connect_encoder(connector_index(device.left_connector),
                            [model](SimTime time) { return model->left_count_at(time); });
      break;
    }
    case scenario::DeviceType::kPotentiometer: {
      auto& pot = pots_[device.name] = std::make_unique<Potentiometer>(device.position);
      const Potentiometer* model = pot.get();
      board.connect_adc(connector_pin(definition, device.connector), [model](SimTime time) { return model->adc_value_at(time); });
      break;
    }
    case scenario::DeviceType::kButton: {
      ButtonSettings settings;
      settings.bounce = static_cast<SimTime>(device.bounce_ms * 1e6 + 0.5);
      settings.pressed_level = device.pressed_level_high;
      settings.seed = mix_seed(scenario_.seed, static_cast<uint64_t>(device.line));
      auto& button = buttons_[device.name] = std::make_unique<BouncingButton>(settings);
      const BouncingButton* model = button.get();
      board.connect_input_pin(connector_pin(definition, device.connector), [model](SimTime time) { return model->level_at(time); });
      break;
    }
    case scenario::DeviceType::kLimitSwitch: {
      limit_switches_.push_back(std::make_unique<LimitSwitch>(
          machine_axis(device.axis), device.at_mm,
          device.side == scenario::LimitSide::kAbove ? sim::LimitSide::kAbove : sim::LimitSide::kBelow));
      const LimitSwitch* model = limit_switches_.back().get();
      board.connect_input_pin(connector_pin(definition, device.connector),
                              [this, model](SimTime) { return machine_ != nullptr && model->active(*machine_); });
      break;
    }
  }
}

// Device schedules are known in advance and go straight into the models; serial input needs
// an event at its time.
void Simulation::apply_timeline() {
  for (size_t index = 0; index < scenario_.timeline.size(); ++index) {
    const scenario::Action& action = scenario_.timeline[index];
    switch (action.type) {
      case scenario::ActionType::kTurn:
        encoders_.at(action.target)->turn(action.time, action.counts, action.over);
        break;
      case scenario::ActionType::kPress: buttons_.at(action.target)->press(action.time); break;
      case scenario::ActionType::kRelease: buttons_.at(action.target)->release(action.time); break;
      case scenario::ActionType::kClick: buttons_.at(action.target)->click(action.time, action.hold); break;
      case scenario::ActionType::kSet: pots_.at(action.target)->set(action.time, action.position); break;
      case scenario::ActionType::kSerial: serial_actions_.post(action.time, index); break;
    }
  }
}

void Simulation::build_vcd() {
  const std::string path = output_path(scenario_.output.vcd);
  if (path.empty() || !options_.write_vcd) return;
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  vcd_ = std::make_unique<VcdRecorder>(path);
  vcd_->set_end_time(duration_);
  for (const scenario::PortLineRef& port : scenario_.output.vcd_ports) {
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
    CableSettings settings;
    settings.delay = config.delay_ns;
    settings.stretch = config.stretch_ns;
    settings.glitch_every = config.glitch_every_us * kMicrosecond;
    settings.glitch_width = config.glitch_width_ns;
    const uint8_t to_port = static_cast<uint8_t>(config.to.port - 'A');
    cables_.push_back(std::make_unique<CableLink>(settings, *slot(config.to.board).board, to_port, delivery_));
    const auto tapped = vcd_inputs_.find(port_key(config.to.board, false, config.to.port));
    if (tapped != vcd_inputs_.end()) {
      VcdRecorder* recorder = vcd_.get();
      const size_t input = tapped->second;
      cables_.back()->set_tap([recorder, input](const PortWaveform& output) { recorder->record_input(input, output); });
    }
    slot(config.from.board).board->add_wire_listener(static_cast<uint8_t>(config.from.port - 'A'), cables_.back().get());
  }
}

// Columns: the pen (with a machine), every socket's model, every knob, pendulum and pot.
void Simulation::build_csv() {
  const std::string path = output_path(scenario_.output.csv);
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
  for (const auto& [name, encoder] : encoders_) {
    const QuadratureEncoder* model = encoder.get();
    probes.push_back({{name + "_counts", 0}, [model](SimTime time) { return static_cast<double>(model->count_at(time)); }});
  }
  for (const auto& [name, pendulum] : pendulums_) {
    const DampedPendulum* model = pendulum.get();
    probes.push_back({{name + "_counts", 0}, [model](SimTime time) { return static_cast<double>(model->count_at(time)); }});
  }
  for (const auto& [name, pot] : pots_) {
    const Potentiometer* model = pot.get();
    probes.push_back({{name + "_adc", 0}, [model](SimTime time) { return static_cast<double>(model->adc_value_at(time)); }});
  }
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  const SimTime interval = static_cast<SimTime>(scenario_.output.csv_interval_ms * 1e6 + 0.5);
  csv_ = std::make_unique<CsvSampler>(scheduler_, path, std::move(probes), interval);
}

}  // namespace stepdance::sim
