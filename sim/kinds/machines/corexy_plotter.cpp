// Machine kind "corexy_plotter": CorexyPlotter on two stepper sockets and a servo socket; its
// page is its travel area.
#include "kinds/machines/corexy_plotter.hpp"

#include "kinds/machines/machine_keys.hpp"

namespace stepdance::sim {
namespace {

using scenario::SocketDevice;
namespace ranges = scenario::ranges;

/// `key` as two numbers in `range` into x and y; reported with `example` otherwise.
void read_pair(scenario::TableReader& reader, const char* key, const scenario::NumberRange& range, const char* example,
               double& x, double& y) {
  const toml::array* pair = reader.array(key);
  if (pair == nullptr) return;
  double values[2] = {0, 0};
  if (scenario::read_number_pair(*pair, values) && scenario::in_range(values[0], range) &&
      scenario::in_range(values[1], range)) {
    x = values[0];
    y = values[1];
  } else {
    reader.error(
        key, "'" + std::string(key) + "' must be two numbers in " + scenario::describe(range) + ", e.g. " + example);
  }
}

std::any read(MachineReading& reading) {
  CorexyConfig config;
  config.motor_a = reading.sockets.take("motor_a", SocketDevice::kStepper, 'A').value_or('A');
  config.motor_b = reading.sockets.take("motor_b", SocketDevice::kStepper, 'B').value_or('B');
  config.pen_servo = reading.sockets.take("pen_servo", SocketDevice::kServo, 'C').value_or('C');
  read_positive(reading.reader, "steps_per_mm", "steps/mm", config.steps_per_mm);
  read_positive(reading.reader, "pen_down_below_us", "µs", config.pen_down_below_us);
  read_pair(reading.reader, "travel_mm", ranges::kPositiveLengthMm, "[300, 218]", config.travel_x_mm,
            config.travel_y_mm);
  read_pair(reading.reader, "start_mm", ranges::kLengthMm, "[120.5, 80]", config.start_x_mm, config.start_y_mm);
  return config;
}

std::unique_ptr<Machine> build(const scenario::MachineConfig& machine, const SocketModels& sockets,
                               const PenTraceSettings& trace) {
  const auto& config = *machine.settings_as<CorexyConfig>();
  StepperDriver* a = sockets.stepper(config.motor_a);
  StepperDriver* b = sockets.stepper(config.motor_b);
  if (a == nullptr || b == nullptr) return nullptr;
  CorexySettings settings = config;
  settings.trace = trace;
  return std::make_unique<CorexyPlotter>(*a, *b, sockets.servo(config.pen_servo), settings);
}

std::optional<TravelArea> page(const scenario::MachineConfig& machine) {
  const auto& config = *machine.settings_as<CorexyConfig>();
  return TravelArea{0, config.travel_x_mm, 0, config.travel_y_mm};
}

}  // namespace

const MachineKind& corexy_plotter_kind() {
  static const MachineKind kind{"corexy_plotter", "xy", read, build, page};
  return kind;
}

}  // namespace stepdance::sim
