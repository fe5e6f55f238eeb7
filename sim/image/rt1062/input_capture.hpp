// Input ports A–D: STEP pulses arriving at a board's input pins reach eFlexPWM capture inputs
// through their pads, as the Teensy backend wires them (input_capture.cpp there).
#pragma once

#include <cstdint>

#include "board/host/wire.hpp"
#include "image/chip/chip_context.hpp"
#include "image/chip/peripheral_bus.hpp"
#include "image/rt1062/flexpwm.hpp"
#include "kernel/scheduler/one_shot_pool.hpp"

namespace stepdance::sim::image {

/// Routes the lead's arriving pulses to the capture circuits. The STEP pin of input port n comes
/// from the board table (kDriverModuleV1.input_ports); its pad decides the capture input
/// (PJRC's Teensy 4.x schematics, RM §11.7 ALT functions and daisy chains):
///   A: pin 4 = GPIO_EMC_06 ALT1 → PWM2 SM0 A (FLEXPWM2_PWMA00_SELECT_INPUT = 0)
///   B: pin 5 = GPIO_EMC_08 ALT1 → PWM2 SM1 A (FLEXPWM2_PWMA01_SELECT_INPUT = 0)
///   C: pin 8 = GPIO_B1_00 ALT6 → PWM1 SM3 A (FLEXPWM1_PWMA03_SELECT_INPUT = 4)
///   D: pin 9 = GPIO_B0_11 ALT2 → PWM2 SM2 B (FLEXPWM2_PWMB02_SELECT_INPUT = 1)
/// An edge reaches the capture only if the pad's mux and the input select say so (read through
/// the bus from IOMUXC; if no IOMUXC answers, the route is taken as set).
class InputCapture {
 public:
  InputCapture(const PeripheralBus& bus, ChipContext& chip, FlexPwm& pwm1, FlexPwm& pwm2);
  InputCapture(const InputCapture&) = delete;
  InputCapture& operator=(const InputCapture&) = delete;

  /// A STEP pulse at input port `port` (0..3). Normally called at pulse.fall_ns: both edges are
  /// captured at their own times (the counter values are those at rise_ns and fall_ns) and the
  /// flags rise now. Called earlier, the edges still to come are scheduled at their times (so a
  /// pulse longer than the counter's 437 µs period keeps its rise interrupt on time).
  /// Context: simulator thread.
  void pulse_arrived(uint8_t port, const ArrivingPulse& pulse);
  /// The DIR line of input port `port` at `now_ns` as the latest pulse left it: its level at the
  /// rising edge until the fall, its level at the falling edge from then on (low before any
  /// pulse). For the board's GPIO side, whose DIR pin the backend reads in its capture ISR.
  /// Context: any.
  bool dir_line(uint8_t port, SimTime now_ns) const;
  /// The Teensy pin of input port `port`'s DIR line (board table), or 255. Context: any.
  static uint8_t dir_pin(uint8_t port);
  /// Edges that did not reach a capture input because the pad was not routed to it. Context: any.
  uint64_t unrouted_edges() const { return unrouted_; }
  /// True while input port `port`'s STEP pad is routed to its capture input (the firmware began
  /// the port). Context: any.
  bool routed(uint8_t port) const;

 private:
  struct Edge {
    uint8_t port;
    bool rising;
    SimTime at_ns;
  };
  static void deliver(void* context, SimTime now, const Edge& edge);
  void edge(uint8_t port, bool rising, SimTime at_ns);

  const PeripheralBus& bus_;
  ChipContext& chip_;
  FlexPwm* pwm_[2];  // PWM1, PWM2
  OneShotPool<Edge> pending_;
  ArrivingPulse latest_[4];
  bool any_[4] = {};
  uint64_t unrouted_ = 0;
};

}  // namespace stepdance::sim::image
