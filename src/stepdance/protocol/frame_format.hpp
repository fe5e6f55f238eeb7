// Output transmission formats: how long the transmitted part of a frame is, and where it starts.
#pragma once

#include <stdint.h>

#include "stepdance/protocol/signals.hpp"

namespace stepdance {

/// Fixed transmission formats of an output port (the original's names). Every format keeps the
/// pulse widths in real microseconds (X 2 µs … E 7 µs, 2 µs gaps), so every decoder reads them;
/// a shorter format holds fewer signals and fits a shorter frame period:
///   OUTPUT_FRAME_32US  any four signals (five unless both Z and E)  frame > 32 µs (40 µs)
///   OUTPUT_FRAME_16US  up to three (XYR or XYT), any single one      frame > 16 µs (20, 25 µs)
///   OUTPUT_FRAME_8US   one signal per frame, X to Z (never E)       frame > 8 µs  (10 µs)
///   OUTPUT_FRAME_4US   X only                                       frame > 4 µs  (10 µs)
/// begin(port) without a format uses the whole frame instead (see layout_for_period).
enum OutputFrameFormat : uint8_t { OUTPUT_FRAME_32US = 0, OUTPUT_FRAME_16US, OUTPUT_FRAME_8US, OUTPUT_FRAME_4US };
constexpr uint8_t kNumOutputFrameFormats = 4;

namespace protocol {

/// Where a frame's signals go. Bit n of a frame word is the level from n to n+1 µs after the
/// frame starts; every line is low again from window_us on.
struct FrameLayout {
  uint8_t window_us = kFrameBitsUs;             ///< transmitted part of the frame (≤ 32 µs)
  uint8_t first_pulse_us = kFirstPulseStartUs;  ///< rising edge of the first STEP pulse
  uint64_t fit_table = 0;                       ///< bit m set: signal set m fits one frame
};

/// Room for slots (pulse + 2 µs gap): a set of signals fits if Σ slot_length_us ≤ room. The last
/// pulse ends 2 µs before first_pulse + Σ slots, and its DIR 1 µs after that, by window_us.
constexpr uint8_t slot_room_us(uint8_t window_us, uint8_t first_pulse_us) {
  return static_cast<uint8_t>(window_us + kInterPulseGapUs - kDirMarginUs - first_pulse_us);
}

/// Microseconds of slots a set of signals needs. Context: any.
constexpr uint8_t slots_used_us(uint8_t mask) {
  uint8_t used = 0;
  for (uint8_t signal = 0; signal < kNumSignals; ++signal) {
    if (mask & (1u << signal)) used = static_cast<uint8_t>(used + slot_length_us(signal));
  }
  return used;
}

/// A layout with its fit table (computed once: at compile time or when a port starts).
constexpr FrameLayout make_frame_layout(uint8_t window_us, uint8_t first_pulse_us) {
  FrameLayout layout{window_us, first_pulse_us, 0};
  for (uint8_t mask = 0; mask <= kAllSignalsMask; ++mask) {
    if (slots_used_us(mask) <= slot_room_us(window_us, first_pulse_us)) layout.fit_table |= uint64_t{1} << mask;
  }
  return layout;
}

/// The layout of a fixed format; an unknown format gets the 32 µs one. Context: any.
constexpr FrameLayout frame_layout(uint8_t format) {
  switch (format) {
    case OUTPUT_FRAME_16US: return make_frame_layout(16, 1);
    case OUTPUT_FRAME_8US: return make_frame_layout(8, 1);
    case OUTPUT_FRAME_4US: return make_frame_layout(4, 1);
    default: return make_frame_layout(kFrameBitsUs, kFirstPulseStartUs);
  }
}

/// The default layout (OUTPUT_FRAME_32US), computed once.
inline constexpr FrameLayout kLayout32Us = frame_layout(OUTPUT_FRAME_32US);

/// The layout that uses a whole frame of period_us: the 32 µs format from a 33 µs frame on,
/// else a window of period − 1 µs from 1 µs (19 µs in a 20 µs frame: XYZ fit; 9 µs in a 10 µs
/// frame: any one signal, E included). Lines are low for the frame's last microsecond at least.
constexpr FrameLayout layout_for_period(uint32_t period_us) {
  if (period_us > kFrameBitsUs) return frame_layout(OUTPUT_FRAME_32US);
  return make_frame_layout(static_cast<uint8_t>(period_us - 1u), 1);
}

/// True if a fixed format's transmission ends before a frame of period_us does, so the lines
/// are low for at least 1 µs between frames and the next first pulse is ≥ 2 µs away. Context: any.
constexpr bool format_fits_period(uint8_t format, uint32_t period_us) {
  return format < kNumOutputFrameFormats && frame_layout(format).window_us < period_us;
}

/// True if a signal fits a frame of the layout on its own (else it could never be sent).
constexpr bool signal_fits(const FrameLayout& layout, uint8_t signal) {
  return signal < kNumSignals && ((layout.fit_table >> (1u << signal)) & 1u) != 0;
}

}  // namespace protocol
}  // namespace stepdance
