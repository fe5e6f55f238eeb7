// Device kind "potentiometer": Potentiometer on A1..A4; `set` actions, a slider on the page.
#include "kinds/devices/potentiometer.hpp"

#include "kinds/device_keys.hpp"
#include "models/potentiometer.hpp"
#include "scenario/names.hpp"

namespace stepdance::sim {
namespace {

constexpr scenario::NumberRange kPosition{0, 1, false, ""};

class PotentiometerDevice : public ModelDevice<Potentiometer> {
 public:
  using ModelDevice::ModelDevice;
  void schedule(const scenario::Action& action) override { model().set(action.time, action.position); }
  void add_probes(const std::string& name, std::vector<DeviceProbe>& probes) const override {
    const Potentiometer* pot = &model();
    probes.push_back({name + "_adc", 0, [pot](SimTime time) { return static_cast<double>(pot->adc_value_at(time)); }});
  }
};

std::any read(DeviceReading& reading) {
  PotentiometerConfig config;
  read_bounded(reading.reader, "position", kPosition, config.position);
  return config;
}

std::unique_ptr<SimDevice> build(const scenario::DeviceConfig& device, DevicePlug& plug) {
  auto built = std::make_unique<PotentiometerDevice>(
      std::make_unique<Potentiometer>(device.settings_as<PotentiometerConfig>()->position));
  const Potentiometer* model = &built->model();
  plug.connect_analog(device.connector, [model](SimTime time) { return model->adc_value_at(time); });
  return built;
}

}  // namespace

const DeviceKind& potentiometer_kind() {
  static const DeviceKind kind{
      "potentiometer",
      "a potentiometer",
      "A1..A4",
      scenario::is_analog_connector,
      {number_key("position", kPosition)},
      read,
      build,
      actions({scenario::ActionType::kSet}),
      PageControl{PageControl::Type::kSlider, kPosition.low, kPosition.high, 0.001, ""},
  };
  return kind;
}

}  // namespace stepdance::sim
