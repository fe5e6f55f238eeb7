// Numeric types, the frame timing names of the original and the position modes shared by every block.
#pragma once

#include <stdint.h>

#include "stepdance/core/frame_period.hpp"

namespace stepdance {

/// A position or distance held by a block, in that block's units (double keeps drift negligible).
using DecimalPosition = volatile double;
/// A knob-style parameter (speed, amplitude, ratio), written by AnalogInput or user code.
using ControlParameter = volatile float;

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

// Names the original library exposed as macros, kept so existing sketches compile. They follow
// the period chosen with set_frame_period_us(), so they are values read at run time (a global
// initialised from them before setup() sees the 40 µs default).
#define CORE_FRAME_PERIOD_US (::stepdance::frame_period_us())
#define CORE_FRAME_FREQ_HZ (::stepdance::frame_rate_hz())
#define CORE_FRAME_PERIOD_S (::stepdance::frame_period_s())
constexpr uint32_t KILOHERTZ_PLUGIN_PERIOD_US = stepdance::kKilohertzPeriodUs;
