// Reads the pulses back out of one frame's STEP/DIR words, as a receiver on the wire would see them.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "stepdance/protocol/pulse_decoder.hpp"
#include "stepdance/protocol/signals.hpp"

namespace stepdance::protocol {

/// One STEP pulse found in a frame's words, with times in whole microseconds from frame start.
struct WirePulse {
  uint8_t rise_us = 0;
  uint8_t fall_us = 0;
  bool dir_at_rise = false;  ///< DIR level during the microsecond the pulse starts
  bool dir_at_fall = false;  ///< DIR level during the microsecond right after it ends
};

/// Finds every STEP pulse in `words` (at most 16) and stores them in `pulses` in time order.
/// A pulse still high at bit 31 ends at 32 µs. Returns the number found. Context: any.
size_t read_wire_pulses(const FrameWords& words, WirePulse* pulses, size_t capacity);

/// Converts a wire pulse into what a capture unit clocked at `clock` would report, with the
/// frame starting at counter value `frame_start_ticks` and DIR sampled at `edge`. Context: any.
CapturedPulse capture_wire_pulse(const WirePulse& pulse, const CaptureClock& clock, uint32_t frame_start_ticks,
                                 DirSampleEdge edge);

}  // namespace stepdance::protocol
