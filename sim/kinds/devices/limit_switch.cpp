// Device kind "limit_switch": LimitSwitch on LIMIT_A..LIMIT_D watching a machine axis, and a hand
// that may hold it (press/release/click, a page button).
#include "kinds/devices/limit_switch.hpp"

#include "kinds/device_keys.hpp"
#include "kinds/machine_kind.hpp"
#include "models/bouncing_button.hpp"
#include "models/limit_switch.hpp"
#include "models/random_stream.hpp"
#include "scenario/names.hpp"

namespace stepdance::sim {
namespace {

void read_axis(DeviceReading& reading, LimitSwitchConfig& config) {
  scenario::TableReader& reader = reading.reader;
  const auto axis = reader.string("axis", scenario::Need::kRequired);
  if (axis) {
    if (*axis == "x" || *axis == "y" || *axis == "z") {
      config.axis = *axis == "x" ? MachineAxis::kX : (*axis == "y" ? MachineAxis::kY : MachineAxis::kZ);
    } else {
      reader.error("axis", "'axis' must be \"x\", \"y\" or \"z\", got \"" + *axis + "\"");
    }
  }
  if (const auto at = reader.number("at_mm", scenario::ranges::kLengthMm, scenario::Need::kRequired))
    config.at_mm = *at;
  if (const auto side = reader.string("side")) {
    if (*side == "below" || *side == "above") {
      config.active_above = *side == "above";
    } else {
      reader.error("side", "'side' must be \"below\" or \"above\", got \"" + *side + "\"");
    }
  }
  const std::optional<scenario::MachineConfig>& machine = reading.context.scenario.machine;
  if (!machine) {
    reader.reporter().error(reader.line(), "a limit_switch needs a [machine] to watch");
  } else if (axis && machine->kind->limit_axes.find(static_cast<char>("xyz"[static_cast<int>(config.axis)])) ==
                         std::string_view::npos) {
    reader.error("axis", "the " + std::string(machine->kind->name) + " machine has no '" + *axis + "' axis");
  }
}

/// A limit switch the machine trips, which a hand may also hold closed (the timeline's press,
/// release and click; the page's button): the line is active while either closes it.
class LimitSwitchDevice : public ModelDevice<LimitSwitch> {
 public:
  LimitSwitchDevice(std::unique_ptr<LimitSwitch> model, std::shared_ptr<BouncingButton> hand)
      : ModelDevice(std::move(model)), hand_(std::move(hand)) {}
  void schedule(const scenario::Action& action) override {
    switch (action.type) {
      case scenario::ActionType::kPress: hand_->press(action.time); break;
      case scenario::ActionType::kRelease: hand_->release(action.time); break;
      case scenario::ActionType::kClick: hand_->click(action.time, action.hold); break;
      default: break;
    }
  }

 private:
  std::shared_ptr<BouncingButton> hand_;
};

/// The hand on the switch: presses and releases only (the switch's own bounce_ms applies to the
/// line, for the hand as for the machine).
std::shared_ptr<BouncingButton> make_hand() {
  ButtonSettings settings;
  settings.bounce = 0;
  return std::make_shared<BouncingButton>(settings);
}

std::any read(DeviceReading& reading) {
  LimitSwitchConfig config;
  read_bounded(reading.reader, "bounce_ms", kBounceMs, config.bounce_ms);
  read_axis(reading, config);
  return config;
}

std::unique_ptr<SimDevice> build(const scenario::DeviceConfig& device, DevicePlug& plug) {
  const auto& config = *device.settings_as<LimitSwitchConfig>();
  const LimitSide side = config.active_above ? LimitSide::kAbove : LimitSide::kBelow;
  auto hand = make_hand();
  auto built =
      std::make_unique<LimitSwitchDevice>(std::make_unique<LimitSwitch>(config.axis, config.at_mm, side), hand);
  const LimitSwitch* model = &built->model();
  std::function<const Machine*()> machine = plug.machine();
  auto bounce = std::make_shared<SwitchBounce>(static_cast<SimTime>(config.bounce_ms * 1e6 + 0.5),
                                               mix_seed(plug.seed(), static_cast<uint64_t>(device.line)));
  plug.connect_digital(device.connector, [model, machine, bounce, hand](SimTime time) {
    const Machine* watched = machine();
    const bool tripped = watched != nullptr && model->active(*watched);
    return bounce->level(time, tripped || hand->pressed_at(time));
  });
  return built;
}

}  // namespace

const DeviceKind& limit_switch_kind() {
  static const DeviceKind kind{
      "limit_switch",
      "a limit switch",
      "LIMIT_A..LIMIT_D",
      scenario::is_limit_connector,
      {DeviceKey{"axis", DeviceKey::Type::kString}, number_key("at_mm", scenario::ranges::kLengthMm),
       DeviceKey{"side", DeviceKey::Type::kString}, number_key("bounce_ms", kBounceMs)},
      read,
      build,
      actions({scenario::ActionType::kPress, scenario::ActionType::kRelease, scenario::ActionType::kClick}),
      PageControl{PageControl::Type::kButton},
  };
  return kind;
}

}  // namespace stepdance::sim
