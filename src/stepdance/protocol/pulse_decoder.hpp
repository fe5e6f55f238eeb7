// Decodes captured STEP pulses into (signal, direction), counting every rejection (pure).
#pragma once

#include <stdint.h>

#include "stepdance/protocol/signals.hpp"

namespace stepdance {

/// How an input port interprets its STEP/DIR lines.
enum InputMode : uint8_t {
  /// Axis by pulse width (2–7 µs), DIR read at the STEP falling edge. The Stepdance default.
  INPUT_MODE_STEPDANCE = 0,
  /// Any pulse is one step of a single configured signal, DIR read at the STEP rising edge,
  /// as ordinary stepper drivers do. For step/dir sources that are not Stepdance boards.
  INPUT_MODE_STEP_DIR = 1,
};

namespace protocol {

/// The STEP edge at which DIR must be sampled.
enum class DirSampleEdge : uint8_t { kRising, kFalling };

/// The DIR sampling edge an input mode needs.
constexpr DirSampleEdge dir_sample_edge(InputMode mode) {
  return mode == INPUT_MODE_STEP_DIR ? DirSampleEdge::kRising : DirSampleEdge::kFalling;
}

/// A capture timer: its rate and the mask of its free-running counter (0xFFFF for 16 bits).
struct CaptureClock {
  uint32_t ticks_per_us = 150;
  uint32_t counter_mask = 0xFFFFu;
};

/// One captured STEP pulse, as the capture hardware reports it.
struct CapturedPulse {
  uint32_t rise_ticks = 0;  ///< counter value at the rising edge
  uint32_t fall_ticks = 0;  ///< counter value at the falling edge (may have wrapped)
  bool dir_high = false;    ///< DIR level sampled at the edge the input mode needs
  /// Whole counter periods (counter_mask + 1 ticks) the pulse lasted beyond the wrapped
  /// difference (fall − rise) mod period: 0 for every pulse shorter than one period. The
  /// backend tracks counter overflow to fill it, so a 439 µs pulse is never read as 2 µs.
  uint32_t extra_periods = 0;
};

/// A pulse from unwrapped tick counts (rise ≤ fall), as a backend that extends the hardware
/// counter (or a simulator that knows the time) reports it. Context: any.
CapturedPulse captured_from_ticks(uint64_t rise_ticks, uint64_t fall_ticks, bool dir_high, const CaptureClock& clock);

/// Pulse width in capture ticks, extra periods included (wider than any 32-bit count). Context: any.
uint64_t width_ticks(const CapturedPulse& pulse, const CaptureClock& clock);

/// Why a pulse was or was not accepted.
enum class PulseVerdict : uint8_t { kAccepted, kTooShort, kTooLong };

/// The result of decoding one pulse.
struct DecodedPulse {
  PulseVerdict verdict = PulseVerdict::kTooShort;
  uint8_t signal = 0;    ///< valid when accepted
  int8_t direction = 0;  ///< +1 forward, −1 reverse; valid when accepted
  uint8_t width_us = 0;  ///< measured width rounded to the nearest µs (ties round down)
};

/// Shortest pulse accepted in STEP_DIR mode, after rounding (shorter ones are glitches): a
/// pulse counts when it rounds to 1 µs, i.e. when it is longer than 0.5 µs.
constexpr uint8_t kStepDirMinWidthUs = 1;

/// Pulse width in whole microseconds, rounded to nearest with ties down, from a capture;
/// saturates at 255 (every width from 254.5 µs up, however long). Context: any.
uint8_t rounded_width_us(const CapturedPulse& pulse, const CaptureClock& clock);

/// Decodes one pulse. STEPDANCE: widths 2..7 µs map to signals X..E, shorter ones are kTooShort,
/// longer ones (of any length) kTooLong. STEP_DIR: any pulse that rounds to at least
/// kStepDirMinWidthUs is one step of step_dir_signal, however long; shorter ones are kTooShort.
/// DIR high means forward.
/// Context: any ISR (pure function).
DecodedPulse decode_pulse(const CapturedPulse& pulse, const CaptureClock& clock, InputMode mode,
                          uint8_t step_dir_signal);

}  // namespace protocol
}  // namespace stepdance
