// Device kind "pendulum": DampedPendulum on ENC1/ENC2; the timeline does not act on it.
#include "kinds/devices/pendulum.hpp"

#include "kinds/device_keys.hpp"
#include "models/damped_pendulum.hpp"
#include "scenario/names.hpp"

namespace stepdance::sim {
namespace {

constexpr scenario::NumberRange kAmplitudeDeg{0, 170, true, "°"};
constexpr scenario::NumberRange kPeriodS{0.01, 3600, false, "s"};
constexpr scenario::NumberRange kDecayS{0.01, 1e6, false, "s"};

class PendulumDevice : public ModelDevice<DampedPendulum> {
 public:
  using ModelDevice::ModelDevice;
  void add_probes(const std::string& name, std::vector<DeviceProbe>& probes) const override {
    const DampedPendulum* pendulum = &model();
    probes.push_back(
        {name + "_counts", 0, [pendulum](SimTime time) { return static_cast<double>(pendulum->count_at(time)); }});
  }
};

std::any read(DeviceReading& reading) {
  PendulumConfig config;
  scenario::TableReader& reader = reading.reader;
  read_pulses_per_revolution(reader, config.pulses_per_revolution);
  read_bounded(reader, "amplitude_deg", kAmplitudeDeg, config.amplitude_deg);
  read_bounded(reader, "period_s", kPeriodS, config.period_s);
  read_bounded(reader, "decay_s", kDecayS, config.decay_s);
  read_bounded(reader, "release_s", run_time_range(reading.context), config.release_s);
  return config;
}

std::unique_ptr<SimDevice> build(const scenario::DeviceConfig& device, DevicePlug& plug) {
  const auto& config = *device.settings_as<PendulumConfig>();
  PendulumSettings settings;
  settings.pulses_per_revolution = config.pulses_per_revolution;
  settings.amplitude_deg = config.amplitude_deg;
  settings.period_s = config.period_s;
  settings.decay_s = config.decay_s;
  settings.release = from_seconds(config.release_s);
  auto built = std::make_unique<PendulumDevice>(std::make_unique<DampedPendulum>(settings));
  const DampedPendulum* model = &built->model();
  plug.connect_encoder(device.connector, [model](SimTime time) { return model->count_at(time); });
  return built;
}

}  // namespace

const DeviceKind& pendulum_kind() {
  static const DeviceKind kind{
      "pendulum",
      "a pendulum",
      "ENC1 or ENC2",
      scenario::is_encoder_connector,
      {integer_key("pulses_per_revolution", kPulsesPerRevolution), number_key("amplitude_deg", kAmplitudeDeg),
       number_key("period_s", kPeriodS), number_key("decay_s", kDecayS),
       number_key("release_s", scenario::ranges::kTimeS)},
      read,
      build,
      0,
      PageControl{},
  };
  return kind;
}

}  // namespace stepdance::sim
