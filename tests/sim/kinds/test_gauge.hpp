// A test-only machine kind, "test_gauge": one stepper moves a pen along x (steps / steps_per_mm),
// always down, on a fixed 100 × 10 mm page. Its model, reader, factory and page state (a "gauge"
// part: its motor's steps) live here and nowhere else: registering it (ScopedKind<MachineRegistry>)
// is all the simulator and its live view need.
#pragma once

#include <memory>

#include "kinds/machine_registry.hpp"

namespace stepdance::sim::test {

/// The gauge's settings: its motor's socket and microsteps per mm.
struct TestGaugeConfig {
  char motor = 'A';
  double steps_per_mm = 80;
};

/// The model: x follows the motor, y stays 0, the pen is always down.
class TestGauge : public Machine {
 public:
  TestGauge(const StepperDriver& motor, double steps_per_mm, const PenTraceSettings& trace)
      : Machine(trace, std::nullopt), motor_(motor), steps_per_mm_(steps_per_mm) {}
  std::optional<double> axis_mm(MachineAxis axis) const override { return pen_axis_mm(axis); }
  int64_t motor_steps() const { return motor_.position_steps(); }

 protected:
  Sample sample(SimTime) override {
    Sample now;
    now.pen = PenPoint{static_cast<double>(motor_.position_steps()) / steps_per_mm_, 0};
    now.down = true;
    return now;
  }

 private:
  const StepperDriver& motor_;
  double steps_per_mm_;
};

inline std::any read_test_gauge(MachineReading& reading) {
  TestGaugeConfig config;
  config.motor = reading.sockets.take("motor", scenario::SocketDevice::kStepper, 'A').value_or('A');
  if (const auto steps = reading.reader.number("steps_per_mm", scenario::NumberRange{0, 1000, true, "steps/mm"})) {
    config.steps_per_mm = *steps;
  }
  return config;
}

inline std::unique_ptr<Machine> build_test_gauge(const scenario::MachineConfig& machine, const SocketModels& sockets,
                                                 const PenTraceSettings& trace) {
  const auto& config = *machine.settings_as<TestGaugeConfig>();
  StepperDriver* motor = sockets.stepper(config.motor);
  if (motor == nullptr) return nullptr;
  return std::make_unique<TestGauge>(*motor, config.steps_per_mm, trace);
}

inline std::optional<TravelArea> test_gauge_page(const scenario::MachineConfig&) { return TravelArea{0, 100, 0, 10}; }

/// The gauge on the live view's page: a "gauge" part, its motor's steps.
inline void add_test_gauge_page_parts(const Machine& machine, SimTime, PageParts& parts) {
  parts.push_back({"gauge", {{"steps", static_cast<const TestGauge&>(machine).motor_steps()}}});
}

inline const MachineKind& test_gauge_kind() {
  static const MachineKind kind{
      "test_gauge", "x", read_test_gauge, build_test_gauge, test_gauge_page, add_test_gauge_page_parts, {"gauge"}};
  return kind;
}

}  // namespace stepdance::sim::test
