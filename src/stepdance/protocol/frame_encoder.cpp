// Frame encoder: picks the signals that fit a frame of the port's layout and lays out their bits.
#include "stepdance/protocol/frame_encoder.hpp"

namespace stepdance::protocol {
namespace {

// Ones from bit `first` for `count` bits (count < 32).
constexpr uint32_t bit_run(uint8_t first, uint8_t count) { return ((1u << count) - 1u) << first; }

// Adds signals from `candidates` (lowest index first) while they still fit beside `chosen`.
// Greedy, not optimal: lower signals (shorter pulses) are tried first, so more signals fit a frame,
// and a signal that does not fit this frame is carried to the next one by the caller.
uint8_t fill(uint8_t chosen, uint8_t candidates, const FrameLayout& layout) {
  for (uint8_t signal = 0; candidates >> signal; ++signal) {
    const uint8_t grown = static_cast<uint8_t>(chosen | (1u << signal));
    if ((candidates & (1u << signal)) && signals_fit(grown, layout)) chosen = grown;
  }
  return chosen;
}

// The step/dir pulse: X's width, X's slot.
constexpr uint8_t kStepDirSlotUs = slot_length_us(SIGNAL_X);

}  // namespace

// Frame context: a table lookup (one bit per subset of the six signals, computed once per layout)
// instead of summing slot lengths on every frame.
bool signals_fit(uint8_t mask, const FrameLayout& layout) {
  return (layout.fit_table >> (mask & kAllSignalsMask)) & 1u;
}

// Frame context. Spec "Frames": each signal at most once per frame, pulses of 2 µs (X) … 7 µs (E), a
// 2 µs gap after each. Signals carried over from the previous frame (priority_mask) are placed first
// so a busy signal cannot starve another. DIR is raised 1 µs before the STEP pulse rises and held
// 1 µs after it falls, so a receiver reading DIR at either edge (ours at the fall, spec "Frames"
// notes; drivers at the rise) reads a settled level. Pulses are laid out in signal order.
EncodedFrame encode_frame(const FrameRequest& request, const FrameLayout& layout) {
  const uint8_t active = request.active_mask & kAllSignalsMask;
  EncodedFrame frame;
  if (active == 0) return frame;
  const uint8_t carried_first = fill(0, active & request.priority_mask, layout);
  const uint8_t sent = signals_fit(active, layout) ? active : fill(carried_first, active, layout);

  frame.sent_mask = sent;
  frame.carried_mask = static_cast<uint8_t>(active & ~sent);
  uint8_t start_us = layout.first_pulse_us;
  for (uint8_t rest = sent; rest != 0; rest &= static_cast<uint8_t>(rest - 1)) {
    const uint8_t signal = lowest_signal(rest);
    const uint8_t width = pulse_width_us(signal);
    frame.words.step_bits |= bit_run(start_us, width);
    if (request.forward_mask & (1u << signal)) {
      frame.words.dir_bits |=
          bit_run(static_cast<uint8_t>(start_us - kDirMarginUs), static_cast<uint8_t>(width + 2 * kDirMarginUs));
    }
    start_us = static_cast<uint8_t>(start_us + slot_length_us(signal));
  }
  return frame;
}

// Step/dir mode repeats X-width (2 µs) pulses with 2 µs gaps, as many as fit the window.
uint8_t step_dir_pulses_per_frame(const FrameLayout& layout) {
  return static_cast<uint8_t>(slot_room_us(layout.window_us, layout.first_pulse_us) / kStepDirSlotUs);
}

// One direction per frame: DIR stays high across all the forward pulses of the frame (from 1 µs before
// the first to 1 µs after the last), which any step/dir driver accepts.
StepDirFrame encode_step_dir_frame(uint32_t count, bool forward, const FrameLayout& layout) {
  StepDirFrame frame;
  const uint8_t room = step_dir_pulses_per_frame(layout);
  frame.sent = static_cast<uint8_t>(count < room ? count : room);
  if (frame.sent == 0) return frame;
  for (uint8_t pulse = 0; pulse < frame.sent; ++pulse) {
    const uint8_t rise_us = static_cast<uint8_t>(layout.first_pulse_us + pulse * kStepDirSlotUs);
    frame.words.step_bits |= bit_run(rise_us, kMinPulseWidthUs);
  }
  if (forward) {
    const uint8_t span_us = static_cast<uint8_t>(frame.sent * kStepDirSlotUs - kInterPulseGapUs + 2 * kDirMarginUs);
    frame.words.dir_bits = bit_run(static_cast<uint8_t>(layout.first_pulse_us - kDirMarginUs), span_us);
  }
  return frame;
}

}  // namespace stepdance::protocol
