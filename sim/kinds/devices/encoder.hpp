// Device kind "encoder": a quadrature knob on ENC1 or ENC2, turned by the timeline.
#pragma once

#include <cstdint>

#include "kinds/device_kind.hpp"

namespace stepdance::sim {

/// An encoder's settings: pulses per revolution per channel (counted ×4) and its count at time 0.
struct EncoderConfig {
  int32_t pulses_per_revolution = 600;
  int64_t start_count = 0;
};

const DeviceKind& encoder_kind();

}  // namespace stepdance::sim
