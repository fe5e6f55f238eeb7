// Device kind "pendulum": a damped pendulum on an encoder's shaft (ENC1 or ENC2).
#pragma once

#include <cstdint>

#include "kinds/device_kind.hpp"

namespace stepdance::sim {

/// A pendulum's settings: held at amplitude_deg from vertical until release_s, then swinging
/// with period_s and its amplitude decaying with time constant decay_s; its encoder's pulses
/// per revolution (counted ×4).
struct PendulumConfig {
  int32_t pulses_per_revolution = 600;
  double amplitude_deg = 30;
  double period_s = 2;
  double decay_s = 30;
  double release_s = 0;
};

const DeviceKind& pendulum_kind();

}  // namespace stepdance::sim
