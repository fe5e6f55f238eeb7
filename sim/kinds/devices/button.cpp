// Device kind "button": BouncingButton on D1, D2 or A1..A4; press/release/click, a page button.
#include "kinds/devices/button.hpp"

#include "kinds/device_keys.hpp"
#include "models/bouncing_button.hpp"
#include "models/random_stream.hpp"
#include "scenario/names.hpp"

namespace stepdance::sim {
namespace {

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
  /// The replay page shows whether the hand holds the button.
  void add_replay_inputs(SimTime now, nlohmann::json& inputs) const override {
    inputs["pressed"] = model().pressed_at(now);
  }
};

std::any read(DeviceReading& reading) {
  ButtonConfig config;
  read_bounded(reading.reader, "bounce_ms", kBounceMs, config.bounce_ms);
  if (const auto level = reading.reader.string("pressed_level")) {
    if (*level == "high" || *level == "low") {
      config.pressed_level_high = *level == "high";
    } else {
      reading.reader.error("pressed_level", "'pressed_level' must be \"high\" or \"low\", got \"" + *level + "\"");
    }
  }
  return config;
}

std::unique_ptr<SimDevice> build(const scenario::DeviceConfig& device, DevicePlug& plug) {
  const auto& config = *device.settings_as<ButtonConfig>();
  ButtonSettings settings;
  settings.bounce = static_cast<SimTime>(config.bounce_ms * 1e6 + 0.5);
  settings.pressed_level = config.pressed_level_high;
  settings.seed = mix_seed(plug.seed(), static_cast<uint64_t>(device.line));
  auto built = std::make_unique<ButtonDevice>(std::make_unique<BouncingButton>(settings));
  const BouncingButton* model = &built->model();
  plug.connect_digital(device.connector, [model](SimTime time) { return model->level_at(time); });
  return built;
}

}  // namespace

const DeviceKind& button_kind() {
  using scenario::ActionType;
  static const DeviceKind kind{
      "button",
      "a button",
      "D1, D2 or A1..A4",
      [](scenario::Connector connector) {
        return scenario::is_digital_connector(connector) || scenario::is_analog_connector(connector);
      },
      {number_key("bounce_ms", kBounceMs), DeviceKey{"pressed_level", DeviceKey::Type::kString}},
      read,
      build,
      actions({ActionType::kPress, ActionType::kRelease, ActionType::kClick}),
      PageControl{PageControl::Type::kButton},
  };
  return kind;
}

}  // namespace stepdance::sim
