// The execution contexts of the engine and the order of the frame's stages.
#pragma once

#include <stdint.h>

namespace stepdance {

/// Where a block runs. The first five are the frame's stages, in execution order.
///
///   frame tick (40 µs) ─► input ports ─► pre-channel ─► channels ─► output ports ─► post-channel
///   1 kHz tick         ─► kilohertz blocks (lower priority, never delays a frame)
///   dance_loop()       ─► loop blocks (parsers, planners, user callbacks)
enum class Stage : uint8_t {
  kInputPorts = 0,
  kPreChannel,
  kChannels,
  kOutputPorts,
  kPostChannel,
  kKilohertz,
  kLoop,
};

/// Number of Stage values.
constexpr uint8_t kNumStages = 7;
/// Number of stages run by each frame (the first five).
constexpr uint8_t kNumFrameStages = 5;

/// A short name for a stage, used in fault details (never null).
const char* to_string(Stage stage);

}  // namespace stepdance

// The original library's plugin context numbers, kept for sketches that name them.
constexpr uint8_t PLUGIN_FRAME_PRE_CHANNEL = 0;
constexpr uint8_t PLUGIN_FRAME_POST_CHANNEL = 1;
constexpr uint8_t PLUGIN_KILOHERTZ = 2;
constexpr uint8_t PLUGIN_LOOP = 3;
constexpr uint8_t PLUGIN_INPUT_PORT = 4;
