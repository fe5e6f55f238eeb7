// Device kind "limit_switch": LimitSwitch on LIMIT_A..LIMIT_D watching a machine axis; no page
// control (the machine trips it).
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
  if (const auto at = reader.number("at_mm", scenario::ranges::kLengthMm, scenario::Need::kRequired)) config.at_mm = *at;
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

std::any read(DeviceReading& reading) {
  LimitSwitchConfig config;
  read_bounded(reading.reader, "bounce_ms", kBounceMs, config.bounce_ms);
  read_axis(reading, config);
  return config;
}

std::unique_ptr<SimDevice> build(const scenario::DeviceConfig& device, DevicePlug& plug) {
  const auto& config = *device.settings_as<LimitSwitchConfig>();
  const LimitSide side = config.active_above ? LimitSide::kAbove : LimitSide::kBelow;
  auto built = std::make_unique<ModelDevice<LimitSwitch>>(std::make_unique<LimitSwitch>(config.axis, config.at_mm, side));
  const LimitSwitch* model = &built->model();
  std::function<const Machine*()> machine = plug.machine();
  auto bounce = std::make_shared<SwitchBounce>(static_cast<SimTime>(config.bounce_ms * 1e6 + 0.5),
                                               mix_seed(plug.seed(), static_cast<uint64_t>(device.line)));
  plug.connect_digital(device.connector, [model, machine, bounce](SimTime time) {
    const Machine* watched = machine();
    return bounce->level(time, watched != nullptr && model->active(*watched));
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
      0,
      PageControl{},
  };
  return kind;
}

}  // namespace stepdance::sim
