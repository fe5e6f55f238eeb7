// Input-port pulses → pads → eFlexPWM capture edges.
#include "image/rt1062/input_capture.hpp"

#include "stepdance/boards/driver_module_v1.hpp"

namespace stepdance::sim::image {
namespace {

constexpr uint32_t kIomuxc = 0x401F8000u;  // RM §11.7

/// One port's capture input: pad mux register and ALT, input-select register and value (RM
/// §11.7: SW_MUX_CTL_PAD_GPIO_EMC_06 0x02C, _EMC_08 0x034, _B1_00 0x17C, _B0_11 0x168;
/// FLEXPWM2_PWMA00/A01/B02_SELECT_INPUT 0x478/0x47C/0x490, FLEXPWM1_PWMA03 0x454).
struct Route {
  uint8_t step_pin;  // Teensy pin (checked against the board table)
  uint16_t mux;
  uint8_t alt;
  uint16_t select;
  uint8_t select_value;
  uint8_t pwm;  // 0 = PWM1, 1 = PWM2
  uint8_t submodule;
  uint8_t channel;  // 0 = A, 1 = B
};
constexpr Route kRoutes[4] = {
    {4, 0x02C, 1, 0x478, 0, 1, 0, 0},
    {5, 0x034, 1, 0x47C, 0, 1, 1, 0},
    {8, 0x17C, 6, 0x454, 4, 0, 3, 0},
    {9, 0x168, 2, 0x490, 1, 1, 2, 1},
};
constexpr bool routes_match_board() {
  for (uint8_t port = 0; port < 4; ++port) {
    if (kDriverModuleV1.input_ports[port].step != kRoutes[port].step_pin) return false;
  }
  return true;
}
static_assert(routes_match_board(), "the board table's input STEP pins moved: update the pad routes");

}  // namespace

InputCapture::InputCapture(const PeripheralBus& bus, ChipContext& chip, FlexPwm& pwm1, FlexPwm& pwm2)
    : bus_(bus), chip_(chip), pwm_{&pwm1, &pwm2}, pending_(chip.scheduler(), &InputCapture::deliver, this) {}

bool InputCapture::routed(uint8_t port) const {
  const Route& route = kRoutes[port];
  uint32_t mux = 0;
  uint32_t select = 0;
  BusRefusal refusal;
  if (!bus_.read(kIomuxc + route.mux, 4, mux, refusal)) return true;  // no IOMUXC on this bus
  if (!bus_.read(kIomuxc + route.select, 4, select, refusal)) return true;
  return (mux & 0xFu) == route.alt && (select & 7u) == route.select_value;  // MUX_MODE, DAISY
}

void InputCapture::edge(uint8_t port, bool rising, SimTime at_ns) {
  if (!routed(port)) {
    ++unrouted_;
    return;
  }
  const Route& route = kRoutes[port];
  pwm_[route.pwm]->capture_edge(route.submodule, route.channel, rising, at_ns);
  chip_.stop_cpu_run();
}

void InputCapture::deliver(void* context, SimTime, const Edge& edge) {
  static_cast<InputCapture*>(context)->edge(edge.port, edge.rising, edge.at_ns);
}

void InputCapture::pulse_arrived(uint8_t port, const ArrivingPulse& pulse) {
  if (port >= 4) return;
  latest_[port] = pulse;
  any_[port] = true;
  const SimTime now = chip_.now_ns();
  if (pulse.rise_ns <= now) {
    edge(port, true, pulse.rise_ns);
  } else {
    pending_.post(pulse.rise_ns, Edge{port, true, pulse.rise_ns});
  }
  if (pulse.fall_ns <= now) {
    edge(port, false, pulse.fall_ns);
  } else {
    pending_.post(pulse.fall_ns, Edge{port, false, pulse.fall_ns});
  }
}

uint8_t InputCapture::dir_pin(uint8_t port) {
  return port < kDriverModuleV1.input_port_count ? kDriverModuleV1.input_ports[port].dir : kNoPin;
}

bool InputCapture::dir_line(uint8_t port, SimTime now_ns) const {
  if (port >= 4 || !any_[port]) return false;
  return now_ns < latest_[port].fall_ns ? latest_[port].dir_at_rise : latest_[port].dir_at_fall;
}

}  // namespace stepdance::sim::image
