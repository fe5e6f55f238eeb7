// Device kind "twist": QwiicTwistModel on a QWIIC bus; turned (detents) and pressed by the
// timeline, a knob with a button on the page.
#include "kinds/devices/twist.hpp"

#include "kinds/device_keys.hpp"
#include "models/qwiic_twist_model.hpp"
#include "scenario/names.hpp"

namespace stepdance::sim {
namespace {

/// A Qwiic Twist's knob has 24 detents a turn (SparkFun's product page).
constexpr int kTwistDetentsPerTurn = 24;

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
  /// The page's knob turns the Twist's detents, 24 per turn of the hand.
  void describe_page_control(nlohmann::json& control) const override {
    control["counts_per_turn"] = kTwistDetentsPerTurn;
  }
  void add_probes(const std::string& name, std::vector<DeviceProbe>& probes) const override {
    QwiicTwistModel* twist = const_cast<QwiicTwistModel*>(&model());  // count_at() applies due events
    probes.push_back(
        {name + "_count", 0, [twist](SimTime time) { return static_cast<double>(twist->count_at(time)); }});
  }
};

std::any read(DeviceReading& reading) {
  read_i2c_address(reading, 0x3F);
  return TwistConfig{};
}

std::unique_ptr<SimDevice> build(const scenario::DeviceConfig& device, DevicePlug& plug) {
  auto built = std::make_unique<TwistDevice>(std::make_unique<QwiicTwistModel>());
  plug.attach_i2c(device.connector, static_cast<uint8_t>(device.i2c_address), &built->model());
  return built;
}

}  // namespace

const DeviceKind& twist_kind() {
  using scenario::ActionType;
  static const DeviceKind kind{
      "twist",
      "a Qwiic Twist knob",
      "QWIIC0 or QWIIC1",
      scenario::is_qwiic_connector,
      {DeviceKey{"address", DeviceKey::Type::kInteger, 0x08, 0x77, ""}},
      read,
      build,
      actions({ActionType::kTurn, ActionType::kPress, ActionType::kRelease, ActionType::kClick}),
      PageControl{PageControl::Type::kKnobWithButton, 0, 0, 1, "detents"},
  };
  return kind;
}

}  // namespace stepdance::sim
