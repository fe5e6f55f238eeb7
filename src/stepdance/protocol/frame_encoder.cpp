// Frame encoder: picks the signals that fit a 32 µs frame and lays out their STEP/DIR bits.
#include "stepdance/protocol/frame_encoder.hpp"

namespace stepdance::protocol {
namespace {

// A set of signals fits if the sum of (width + gap) is at most 31: the first pulse starts at
// 2 µs and the last must end by bit 31, i.e. 2 + Σ(w + 2) − 2 ≤ 31.
constexpr uint8_t kFrameRoomUs = kLastPulseBitUs;

constexpr uint8_t slots_used_us(uint8_t mask) {
  uint8_t used = 0;
  for (uint8_t signal = 0; signal < kNumSignals; ++signal) {
    if (mask & (1u << signal)) used = static_cast<uint8_t>(used + slot_length_us(signal));
  }
  return used;
}

// Bit m is set when signal set m fits in one frame; computed at compile time.
constexpr uint64_t fit_table() {
  uint64_t table = 0;
  for (uint8_t mask = 0; mask <= kAllSignalsMask; ++mask) {
    if (slots_used_us(mask) <= kFrameRoomUs) table |= uint64_t{1} << mask;
  }
  return table;
}
constexpr uint64_t kFitTable = fit_table();

// Ones from bit `first` for `count` bits (count < 32).
constexpr uint32_t bit_run(uint8_t first, uint8_t count) { return ((1u << count) - 1u) << first; }

// Adds signals from `candidates` (lowest index first) while they still fit beside `chosen`.
uint8_t fill(uint8_t chosen, uint8_t candidates) {
  for (uint8_t signal = 0; candidates >> signal; ++signal) {
    const uint8_t grown = static_cast<uint8_t>(chosen | (1u << signal));
    if ((candidates & (1u << signal)) && signals_fit(grown)) chosen = grown;
  }
  return chosen;
}

}  // namespace

bool signals_fit(uint8_t mask) { return (kFitTable >> (mask & kAllSignalsMask)) & 1u; }

EncodedFrame encode_frame(const FrameRequest& request) {
  const uint8_t active = request.active_mask & kAllSignalsMask;
  EncodedFrame frame;
  if (active == 0) return frame;
  const uint8_t carried_first = fill(0, active & request.priority_mask);
  const uint8_t sent = signals_fit(active) ? active : fill(carried_first, active);

  frame.sent_mask = sent;
  frame.carried_mask = static_cast<uint8_t>(active & ~sent);
  uint8_t start_us = kFirstPulseStartUs;
  for (uint8_t signal = 0; sent >> signal; ++signal) {
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
