// Machine kind "polar": PolarTurntable on two stepper sockets and an optional servo socket; its
// page is the drawing's bounding box.
#include "kinds/machines/polar_turntable.hpp"

#include "kinds/machines/machine_keys.hpp"

namespace stepdance::sim {
namespace {

using scenario::SocketDevice;

std::any read(MachineReading& reading) {
  PolarConfig config;
  config.angle = reading.sockets.take("angle", SocketDevice::kStepper, 'A').value_or('A');
  config.radius = reading.sockets.take("radius", SocketDevice::kStepper, 'B').value_or('B');
  config.pen_servo = reading.sockets.take("pen_servo", SocketDevice::kServo, std::nullopt);
  read_positive(reading.reader, "steps_per_rev", "steps", config.steps_per_rev);
  read_positive(reading.reader, "steps_per_mm", "steps/mm", config.steps_per_mm);
  read_positive(reading.reader, "pen_down_below_us", "µs", config.pen_down_below_us);
  return config;
}

std::unique_ptr<Machine> build(const scenario::MachineConfig& machine, const SocketModels& sockets,
                               const PenTraceSettings& trace) {
  const auto& config = *machine.settings_as<PolarConfig>();
  StepperDriver* angle = sockets.stepper(config.angle);
  StepperDriver* radius = sockets.stepper(config.radius);
  if (angle == nullptr || radius == nullptr) return nullptr;
  PolarSettings settings = config;
  settings.trace = trace;
  return std::make_unique<PolarTurntable>(*angle, *radius,
                                          config.pen_servo ? sockets.servo(*config.pen_servo) : nullptr, settings);
}

/// The page's "table" part: the table's angle and the pen's radius, to turn the paper by.
void add_page_parts(const Machine& machine, SimTime, PageParts& parts) {
  const auto* table = dynamic_cast<const PolarTurntable*>(&machine);
  if (table == nullptr) return;  // not built by this kind
  parts.push_back({"table", {{"angle_rad", table->angle_rad()}, {"radius_mm", table->radius_mm()}}});
}

}  // namespace

const MachineKind& polar_turntable_kind() {
  static const MachineKind kind{"polar", "x", read, build, nullptr, add_page_parts, {"table"}};
  return kind;
}

}  // namespace stepdance::sim
