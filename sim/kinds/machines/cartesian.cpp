// Machine kind "cartesian": CartesianMachine on up to four stepper sockets; its page is the
// drawing's bounding box.
#include "kinds/machines/cartesian.hpp"

#include <algorithm>

#include "kinds/machines/machine_keys.hpp"

namespace stepdance::sim {
namespace {

using scenario::SocketDevice;

void read_steps_per_mm(scenario::TableReader& reader, CartesianConfig& config) {
  const toml::table* per_axis = reader.table("steps_per_mm");
  if (per_axis == nullptr) return;
  scenario::TableReader axes(*per_axis, "steps_per_mm", reader.reporter());
  read_positive(axes, "x", "steps/mm", config.x_steps_per_mm);
  read_positive(axes, "y", "steps/mm", config.y_steps_per_mm);
  read_positive(axes, "z", "steps/mm", config.z_steps_per_mm);
  read_positive(axes, "e", "steps/mm", config.e_steps_per_mm);
  axes.finish();
}

std::any read(MachineReading& reading) {
  CartesianConfig config;
  scenario::TableReader& reader = reading.reader;
  config.x = reading.sockets.take("x", SocketDevice::kStepper, std::nullopt);
  config.y = reading.sockets.take("y", SocketDevice::kStepper, std::nullopt);
  config.z = reading.sockets.take("z", SocketDevice::kStepper, std::nullopt);
  config.e = reading.sockets.take("e", SocketDevice::kStepper, std::nullopt);
  read_steps_per_mm(reader, config);
  if (const auto threshold = reader.number("pen_down_at_or_below_mm", scenario::ranges::kLengthMm)) {
    config.pen_down_at_or_below_mm = *threshold;
  }
  if (const auto draw = reader.string("draw")) {
    if (*draw == "z" || *draw == "extruding") {
      config.draws_while_extruding = *draw == "extruding";
    } else {
      reader.error("draw",
                   "'draw' must be \"z\" (the pen is down while z is low) or \"extruding\", got \"" + *draw + "\"");
    }
    if (config.draws_while_extruding && !config.e) reader.error("draw", "'draw = \"extruding\"' needs an 'e' socket");
  }
  return config;
}

std::unique_ptr<Machine> build(const scenario::MachineConfig& machine, const SocketModels& sockets,
                               const PenTraceSettings& trace) {
  const auto& config = *machine.settings_as<CartesianConfig>();
  auto axis = [&sockets](const std::optional<char>& port) { return port ? sockets.stepper(*port) : nullptr; };
  CartesianSettings settings = config;
  settings.trace = trace;
  // One axis steps at a time, so the pen stair-steps up to a step off the true path on each
  // axis: the stored toolpath smooths that out (its length is then the path's, not the stairs').
  const double coarsest_step_mm = 1.0 / std::min(config.x_steps_per_mm, config.y_steps_per_mm);
  settings.trace.tolerance_mm = std::max(trace.tolerance_mm, 1.5 * coarsest_step_mm);
  return std::make_unique<CartesianMachine>(
      CartesianDrivers{axis(config.x), axis(config.y), axis(config.z), axis(config.e)}, settings);
}

}  // namespace

const MachineKind& cartesian_kind() {
  static const MachineKind kind{"cartesian", "xyz", read, build};
  return kind;
}

}  // namespace stepdance::sim
