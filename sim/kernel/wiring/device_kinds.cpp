// The simulator's input device kinds: encoder, potentiometer, button, limit switch, pendulum,
// five-bar arm — each a builder that makes its model and plugs it into the board.
#include "wiring/device_kinds.hpp"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "models/bouncing_button.hpp"
#include "models/damped_pendulum.hpp"
#include "models/five_bar_arm.hpp"
#include "models/qwiic_twist_model.hpp"
#include "models/ssd1306_display.hpp"
#include "output/screen_png.hpp"
#include "models/limit_switch.hpp"
#include "models/potentiometer.hpp"
#include "models/quadrature_encoder.hpp"
#include "models/random_stream.hpp"

namespace stepdance::sim {
namespace {

using scenario::Connector;
using scenario::DeviceConfig;

/// Index of a connector within its group (ENC1 → 0, A3 → 2, D2 → 1, LIMIT_C → 2).
uint8_t connector_index(Connector connector) {
  switch (connector) {
    case Connector::kEnc1: case Connector::kA1: case Connector::kD1: case Connector::kLimitA: case Connector::kQwiic0: return 0;
    case Connector::kEnc2: case Connector::kA2: case Connector::kD2: case Connector::kLimitB: case Connector::kQwiic1: return 1;
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

/// A CSV column of integer counts read from a model.
template <typename Read>
CsvProbe counts_probe(const std::string& column, Read read) {
  return {{column, 0}, [read](SimTime time) { return static_cast<double>(read(time)); }};
}

class EncoderDevice : public ModelDevice<QuadratureEncoder> {
 public:
  using ModelDevice::ModelDevice;
  void schedule(const scenario::Action& action) override { model().turn(action.time, action.counts, action.over); }
  void add_probes(const std::string& name, std::vector<CsvProbe>& probes) const override {
    const QuadratureEncoder* encoder = &model();
    probes.push_back(counts_probe(name + "_counts", [encoder](SimTime time) { return encoder->count_at(time); }));
  }
};

class PotentiometerDevice : public ModelDevice<Potentiometer> {
 public:
  using ModelDevice::ModelDevice;
  void schedule(const scenario::Action& action) override { model().set(action.time, action.position); }
  void add_probes(const std::string& name, std::vector<CsvProbe>& probes) const override {
    const Potentiometer* pot = &model();
    probes.push_back(counts_probe(name + "_adc", [pot](SimTime time) { return pot->adc_value_at(time); }));
  }
};

class ButtonDevice : public ModelDevice<BouncingButton> {
 public:
  using ModelDevice::ModelDevice;
  void schedule(const scenario::Action& action) override {
    switch (action.type) {
      case scenario::ActionType::kPress: model().press(action.time); break;
      case scenario::ActionType::kRelease: model().release(action.time); break;
      case scenario::ActionType::kClick: model().click(action.time, action.hold); break;
      default: break;
    }
  }
};

class PendulumDevice : public ModelDevice<DampedPendulum> {
 public:
  using ModelDevice::ModelDevice;
  void add_probes(const std::string& name, std::vector<CsvProbe>& probes) const override {
    const DampedPendulum* pendulum = &model();
    probes.push_back(counts_probe(name + "_counts", [pendulum](SimTime time) { return pendulum->count_at(time); }));
  }
};

class ArmDevice : public ModelDevice<FiveBarArm> {
 public:
  using ModelDevice::ModelDevice;
  void add_probes(const std::string& name, std::vector<CsvProbe>& probes) const override {
    const FiveBarArm* arm = &model();
    probes.push_back(counts_probe(name + "_right_counts", [arm](SimTime time) { return arm->right_count_at(time); }));
    probes.push_back(counts_probe(name + "_left_counts", [arm](SimTime time) { return arm->left_count_at(time); }));
  }
};

std::unique_ptr<SimDevice> build_encoder(const DeviceConfig& device, DeviceSocket& socket) {
  auto built = std::make_unique<EncoderDevice>(
      std::make_unique<QuadratureEncoder>(device.pulses_per_revolution, device.start_count));
  const QuadratureEncoder* model = &built->model();
  socket.board.connect_encoder(connector_index(device.connector), [model](SimTime time) { return model->count_at(time); });
  return built;
}

std::unique_ptr<SimDevice> build_potentiometer(const DeviceConfig& device, DeviceSocket& socket) {
  auto built = std::make_unique<PotentiometerDevice>(std::make_unique<Potentiometer>(device.position));
  const Potentiometer* model = &built->model();
  socket.board.connect_adc(connector_pin(socket.board.definition(), device.connector),
                           [model](SimTime time) { return model->adc_value_at(time); });
  return built;
}

std::unique_ptr<SimDevice> build_button(const DeviceConfig& device, DeviceSocket& socket) {
  ButtonSettings settings;
  settings.bounce = static_cast<SimTime>(device.bounce_ms * 1e6 + 0.5);
  settings.pressed_level = device.pressed_level_high;
  settings.seed = mix_seed(socket.scenario_seed, static_cast<uint64_t>(device.line));
  auto built = std::make_unique<ButtonDevice>(std::make_unique<BouncingButton>(settings));
  const BouncingButton* model = &built->model();
  socket.board.connect_input_pin(connector_pin(socket.board.definition(), device.connector),
                                 [model](SimTime time) { return model->level_at(time); });
  return built;
}

std::unique_ptr<SimDevice> build_limit_switch(const DeviceConfig& device, DeviceSocket& socket) {
  const auto side = device.side == scenario::LimitSide::kAbove ? sim::LimitSide::kAbove : sim::LimitSide::kBelow;
  auto built = std::make_unique<ModelDevice<LimitSwitch>>(
      std::make_unique<LimitSwitch>(machine_axis(device.axis), device.at_mm, side));
  const LimitSwitch* model = &built->model();
  std::function<const Machine*()> machine = socket.machine;
  auto bounce = std::make_shared<SwitchBounce>(static_cast<SimTime>(device.bounce_ms * 1e6 + 0.5),
                                               mix_seed(socket.scenario_seed, static_cast<uint64_t>(device.line)));
  socket.board.connect_input_pin(connector_pin(socket.board.definition(), device.connector),
                                 [model, machine, bounce](SimTime time) {
                                   const Machine* watched = machine();
                                   return bounce->level(time, watched != nullptr && model->active(*watched));
                                 });
  return built;
}

std::unique_ptr<SimDevice> build_pendulum(const DeviceConfig& device, DeviceSocket& socket) {
  PendulumSettings settings;
  settings.pulses_per_revolution = device.pulses_per_revolution;
  settings.amplitude_deg = device.amplitude_deg;
  settings.period_s = device.period_s;
  settings.decay_s = device.decay_s;
  settings.release = from_seconds(device.release_s);
  auto built = std::make_unique<PendulumDevice>(std::make_unique<DampedPendulum>(settings));
  const DampedPendulum* model = &built->model();
  socket.board.connect_encoder(connector_index(device.connector), [model](SimTime time) { return model->count_at(time); });
  return built;
}

std::unique_ptr<SimDevice> build_five_bar_arm(const DeviceConfig& device, DeviceSocket& socket) {
  FiveBarArmSettings settings;
  settings.pulses_per_revolution = device.pulses_per_revolution;
  for (const auto& [x, y] : device.path_mm) settings.path_mm.push_back(PenPoint{x, y});
  settings.dwell_s = device.dwell_s;
  settings.speed_mm_per_s = device.speed_mm_per_s;
  settings.start = from_seconds(device.start_s);
  constexpr double kDegreeRad = 3.14159265358979323846 / 180;
  settings.right_min_rad = device.right_min_deg * kDegreeRad;
  settings.left_max_rad = device.left_max_deg * kDegreeRad;
  auto built = std::make_unique<ArmDevice>(std::make_unique<FiveBarArm>(settings));
  const FiveBarArm* model = &built->model();
  socket.board.connect_encoder(connector_index(device.connector), [model](SimTime time) { return model->right_count_at(time); });
  socket.board.connect_encoder(connector_index(device.left_connector),
                               [model](SimTime time) { return model->left_count_at(time); });
  return built;
}

/// An OLED picture's file name: "<name>-<t>s.png" at a snapshot time (ms precision).
std::string oled_snapshot_name(const std::string& name, SimTime time) {
  char stamp[32];
  std::snprintf(stamp, sizeof stamp, "-%.3fs", to_seconds(time));
  return name + stamp + ".png";
}

/// "<name>-<t>s.png" at each snapshot time, then "<name>.png" for the end of the run.
std::vector<std::string> oled_output_names(const DeviceConfig& device) {
  std::vector<std::string> names;
  for (double seconds : device.snapshots_s) names.push_back(oled_snapshot_name(device.name, from_seconds(seconds)));
  names.push_back(device.name + ".png");
  return names;
}

/// The OLED: its screen as PNGs, 4 px per pixel: "<name>.png" at the end and
/// "<name>-<t>s.png" at each snapshot time.
class OledDevice : public ModelDevice<Ssd1306Display> {
 public:
  using ModelDevice::ModelDevice;
  void write_outputs(const std::string& name, const std::function<std::string(const std::string&)>& path_for,
                     std::vector<std::string>& files) override {
    model().finish();
    for (const auto& [time, picture] : model().snapshots()) write(picture, path_for(oled_snapshot_name(name, time)), files);
    write(model().image(), path_for(name + ".png"), files);
  }

 private:
  static void write(const OledImage& picture, const std::string& path, std::vector<std::string>& files) {
    std::filesystem::create_directories(std::filesystem::path(path).parent_path());
    write_screen_png(path, std::vector<bool>(picture.lit.begin(), picture.lit.end()), OledImage::kWidth,
                     OledImage::kHeight, 4);
    files.push_back(path);
  }
};

class TwistDevice : public ModelDevice<QwiicTwistModel> {
 public:
  using ModelDevice::ModelDevice;
  void schedule(const scenario::Action& action) override {
    switch (action.type) {
      case scenario::ActionType::kTurn: model().turn(action.time, action.counts, action.over); break;
      case scenario::ActionType::kPress: model().press(action.time); break;
      case scenario::ActionType::kRelease: model().release(action.time); break;
      case scenario::ActionType::kClick: model().click(action.time, action.hold); break;
      default: break;
    }
  }
  void add_probes(const std::string& name, std::vector<CsvProbe>& probes) const override {
    QwiicTwistModel* twist = const_cast<QwiicTwistModel*>(&model());  // count_at() applies due events
    probes.push_back(counts_probe(name + "_count", [twist](SimTime time) { return twist->count_at(time); }));
  }
};

std::unique_ptr<SimDevice> build_oled(const DeviceConfig& device, DeviceSocket& socket) {
  auto built = std::make_unique<OledDevice>(std::make_unique<Ssd1306Display>());
  std::vector<SimTime> times;
  for (double seconds : device.snapshots_s) times.push_back(from_seconds(seconds));
  built->model().set_snapshot_times(std::move(times));
  socket.board.attach_i2c_device(connector_index(device.connector), static_cast<uint8_t>(device.i2c_address),
                                 &built->model());
  return built;
}

std::unique_ptr<SimDevice> build_twist(const DeviceConfig& device, DeviceSocket& socket) {
  auto built = std::make_unique<TwistDevice>(std::make_unique<QwiicTwistModel>());
  socket.board.attach_i2c_device(connector_index(device.connector), static_cast<uint8_t>(device.i2c_address),
                                 &built->model());
  return built;
}

using Builder = std::unique_ptr<SimDevice> (*)(const DeviceConfig&, DeviceSocket&);

/// One row per kind (the scenario reader's own table, names.cpp, lists the same kinds).
constexpr std::pair<scenario::DeviceType, Builder> kBuilders[] = {
    {scenario::DeviceType::kEncoder, build_encoder},
    {scenario::DeviceType::kPotentiometer, build_potentiometer},
    {scenario::DeviceType::kButton, build_button},
    {scenario::DeviceType::kLimitSwitch, build_limit_switch},
    {scenario::DeviceType::kPendulum, build_pendulum},
    {scenario::DeviceType::kFiveBarArm, build_five_bar_arm},
    {scenario::DeviceType::kOled, build_oled},
    {scenario::DeviceType::kTwist, build_twist},
};

using Namer = std::vector<std::string> (*)(const DeviceConfig&);

/// The kinds that write files of their own, one row each.
constexpr std::pair<scenario::DeviceType, Namer> kNamers[] = {
    {scenario::DeviceType::kOled, oled_output_names},
};

}  // namespace

std::vector<std::string> device_output_names(const DeviceConfig& device) {
  for (const auto& [type, names] : kNamers) {
    if (type == device.type) return names(device);
  }
  return {};
}

std::unique_ptr<SimDevice> build_device_model(const DeviceConfig& device, DeviceSocket& socket) {
  for (const auto& [type, build] : kBuilders) {
    if (type == device.type) return build(device, socket);
  }
  throw std::logic_error("device '" + device.name + "': no builder for its kind");  // every kind has a row
}

}  // namespace stepdance::sim
