// Numeric types, frame timing constants and the position modes shared by every block.
#pragma once

#include <stdint.h>

namespace stepdance {

/// A position or distance held by a block, in that block's units (double keeps drift negligible).
using DecimalPosition = volatile double;
/// A knob-style parameter (speed, amplitude, ratio), written by AnalogInput or user code.
using ControlParameter = volatile float;

/// Frame period of the real-time engine in microseconds (25 kHz).
constexpr uint32_t kFramePeriodUs = 40;
/// Frame rate in hertz.
constexpr uint32_t kFrameRateHz = 1000000 / kFramePeriodUs;
/// Frame period in seconds.
constexpr double kFramePeriodS = kFramePeriodUs / 1e6;
/// Period of the 1 kHz context in microseconds.
constexpr uint32_t kKilohertzPeriodUs = 1000;
/// Frames per kilohertz tick.
constexpr uint32_t kFramesPerKilohertzTick = kKilohertzPeriodUs / kFramePeriodUs;

/// How a value moves through a BlockPort: as a change, or as a position.
enum PositionMode : uint8_t {
  INCREMENTAL = 0,  ///< values are changes, several writers add up
  ABSOLUTE = 1,     ///< values are positions, the last writer wins
  GLOBAL = 2,       ///< like ABSOLUTE, after adopting the machine's real position (deep pull)
};

/// Direction a BlockPort faces in a deep (state-synchronising) chain.
enum BlockPortDirection : uint8_t {
  BLOCKPORT_INPUT = 0,
  BLOCKPORT_OUTPUT = 1,
  BLOCKPORT_UNDEFINED = 2,
};

/// Selector for Encoder::set_latch.
enum LatchSide : uint8_t { MIN = 0, MAX = 1 };

/// Standard motion-stream resolution between modules: 0.01 mm per step.
constexpr double STANDARD_RATIO_MM = 0.01;
/// The same resolution in inches per step.
constexpr double STANDARD_RATIO_IN = 0.0003937;

}  // namespace stepdance

// Names the original library exposed as macros; kept so existing sketches compile.
constexpr uint32_t CORE_FRAME_PERIOD_US = stepdance::kFramePeriodUs;
constexpr uint32_t CORE_FRAME_FREQ_HZ = stepdance::kFrameRateHz;
constexpr double CORE_FRAME_PERIOD_S = stepdance::kFramePeriodS;
constexpr uint32_t KILOHERTZ_PLUGIN_PERIOD_US = stepdance::kKilohertzPeriodUs;
