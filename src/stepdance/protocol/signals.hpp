// Motion-stream vocabulary: the six axis-coded signals, their pulse widths and the frame layout.
#pragma once

#include <stdint.h>

namespace stepdance {

/// Axis-coded signals, in pulse-width order. The axis a signal drives is the designer's choice.
enum Signal : uint8_t {
  SIGNAL_X = 0,  ///< 2 µs pulse
  SIGNAL_Y = 1,  ///< 3 µs pulse
  SIGNAL_R = 2,  ///< 4 µs pulse
  SIGNAL_T = 3,  ///< 5 µs pulse (θ)
  SIGNAL_Z = 4,  ///< 6 µs pulse
  SIGNAL_E = 5,  ///< 7 µs pulse
};

/// Number of distinct signals on one port.
constexpr uint8_t kNumSignals = 6;
constexpr uint8_t NUM_SIGNALS = kNumSignals;
/// Bit mask with every signal set.
constexpr uint8_t kAllSignalsMask = (1u << kNumSignals) - 1;

/// The lowest signal in a non-empty mask of signals (bit n = signal n). Frame code walks masks
/// with it, `for (m = mask; m != 0; m &= m - 1) use(lowest_signal(m));`, visiting only the set
/// signals in ascending order (one count-trailing-zeros instruction each on the M7). Context: any.
inline uint8_t lowest_signal(uint8_t mask) { return static_cast<uint8_t>(__builtin_ctz(mask)); }

/// Step direction as carried on DIR: high means forward.
constexpr uint8_t DIRECTION_FORWARD = 1;
constexpr uint8_t DIRECTION_REVERSE = 0;

namespace protocol {

/// Width of the narrowest signal (X) in microseconds.
constexpr uint8_t kMinPulseWidthUs = 2;
/// Width of the widest signal (E) in microseconds.
constexpr uint8_t kMaxPulseWidthUs = kMinPulseWidthUs + kNumSignals - 1;
/// Time from frame start to the first possible STEP rising edge.
constexpr uint8_t kFirstPulseStartUs = 2;
/// Idle time between consecutive pulses of one frame.
constexpr uint8_t kInterPulseGapUs = 2;
/// DIR of a forward signal rises this long before STEP rises and falls this long after STEP falls.
constexpr uint8_t kDirMarginUs = 1;
/// Length of the transmitted part of a frame: one bit per microsecond, 32 bits.
constexpr uint8_t kFrameBitsUs = 32;
/// Last microsecond slot a pulse may occupy (bit 31). Bit 31 is always low in practice.
constexpr uint8_t kLastPulseBitUs = kFrameBitsUs - 1;

/// STEP pulse width of a signal in microseconds. Precondition: signal < kNumSignals.
constexpr uint8_t pulse_width_us(uint8_t signal) { return static_cast<uint8_t>(kMinPulseWidthUs + signal); }

/// Microseconds of frame a signal occupies: its pulse plus the gap after it.
constexpr uint8_t slot_length_us(uint8_t signal) {
  return static_cast<uint8_t>(pulse_width_us(signal) + kInterPulseGapUs);
}

/// One frame's line levels: bit n is the level from n µs to n+1 µs after the frame starts.
struct FrameWords {
  uint32_t step_bits = 0;
  uint32_t dir_bits = 0;
};

}  // namespace protocol
}  // namespace stepdance
