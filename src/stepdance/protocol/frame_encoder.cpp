// Frame encoder: picks the signals that fit a 32 µs frame and lays out their STEP/DIR bits.
#include "stepdance/protocol/frame_encoder.hpp"

namespace stepdance::protocol {
namespace {

// A set of signals fits if the sum of (width + gap) is at most 31: the first pulse starts at
// 2 µs and the last must end by bit 31, i.e. 2 + Σ(w + 2) − 2 ≤ 31.
constexpr uint8_t kFrameRoomUs = kLastPulseBitUs;

uint8_t slots_used_us(uint8_t mask) {
  uint8_t used = 0;
  for (uint8_t signal = 0; signal < kNumSignals; ++signal) {
    if (mask & (1u << signal)) used = static_cast<uint8_t>(used + slot_length_us(signal));
  }
  return used;
}

// Ones from bit `first` for `count` bits.
constexpr uint32_t bit_run(uint8_t first, uint8_t count) {
  return ((count >= 32 ? 0xFFFFFFFFu : ((1u << count) - 1u))) << first;
}

// Adds signals from `candidates` (lowest index first) while they still fit beside `chosen`.
uint8_t fill(uint8_t chosen, uint8_t candidates) {
  for (uint8_t signal = 0; signal < kNumSignals; ++signal) {
    const uint8_t bit = static_cast<uint8_t>(1u << signal);
    if ((candidates & bit) && signals_fit(static_cast<uint8_t>(chosen | bit))) chosen |= bit;
  }
  return chosen;
}

}  // namespace

bool signals_fit(uint8_t mask) { return slots_used_us(mask & kAllSignalsMask) <= kFrameRoomUs; }

EncodedFrame encode_frame(const FrameRequest& request) {
  const uint8_t active = request.active_mask & kAllSignalsMask;
  const uint8_t carried_first = fill(0, active & request.priority_mask);
  const uint8_t sent = fill(carried_first, active);

  EncodedFrame frame;
  frame.sent_mask = sent;
  frame.carried_mask = static_cast<uint8_t>(active & ~sent);
  uint8_t start_us = kFirstPulseStartUs;
  for (uint8_t signal = 0; signal < kNumSignals; ++signal) {
    if (!(sent & (1u << signal))) continue;
    const uint8_t width = pulse_width_us(signal);
    frame.words.step_bits |= bit_run(start_us, width);
    if (request.forward_mask & (1u << signal)) {
      frame.words.dir_bits |= bit_run(static_cast<uint8_t>(start_us - kDirMarginUs),
                                      static_cast<uint8_t>(width + 2 * kDirMarginUs));
    }
    start_us = static_cast<uint8_t>(start_us + slot_length_us(signal));
  }
  return frame;
}

}  // namespace stepdance::protocol
