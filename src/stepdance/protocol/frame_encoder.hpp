// Encodes one frame's signals into STEP/DIR bit words (pure; runs in the frame ISR).
#pragma once

#include <stdint.h>

#include "stepdance/protocol/frame_format.hpp"
#include "stepdance/protocol/signals.hpp"

namespace stepdance::protocol {

/// What a port wants to send in one frame. Bit i of each mask refers to signal i.
struct FrameRequest {
  uint8_t active_mask = 0;    ///< signals with a pulse to send
  uint8_t forward_mask = 0;   ///< of those, the ones stepping forward (DIR high)
  uint8_t priority_mask = 0;  ///< of those, the ones carried from an earlier frame (served first)
};

/// The encoded frame and which of the requested signals it holds.
struct EncodedFrame {
  FrameWords words;
  uint8_t sent_mask = 0;     ///< signals placed in this frame
  uint8_t carried_mask = 0;  ///< requested signals that did not fit and must be sent later
};

/// True if every signal in mask fits into one frame of the layout (Σ (width + 2 µs) ≤
/// slot_room_us: 31 µs for OUTPUT_FRAME_32US). Context: any.
bool signals_fit(uint8_t mask, const FrameLayout& layout = kLayout32Us);

/// Encodes a frame: chooses the signals to send (carried ones first, then by index, each taken
/// if it still fits), then lays them out in index order from the layout's first pulse (2 µs in
/// OUTPUT_FRAME_32US, 1 µs in the shorter ones) with 2 µs gaps. A forward signal's DIR is high
/// from 1 µs before its STEP rises to 1 µs after it falls; DIR is low otherwise. Signals that do
/// not fit are returned in carried_mask, never dropped.
/// Context: any (pure function).
EncodedFrame encode_frame(const FrameRequest& request, const FrameLayout& layout = kLayout32Us);

/// Pulses of one plain step/dir frame: 2 µs STEP pulses 2 µs apart from the layout's first
/// pulse, all in one direction, DIR high over all of them (from 1 µs before the first rise to
/// 1 µs after the last fall) when forward. How many fit: slot_room_us / 4 (7 in 32 µs, 2 in a
/// 10 µs frame's 9 µs window, 1 in 4 µs). Context: any.
uint8_t step_dir_pulses_per_frame(const FrameLayout& layout);

/// Encodes up to step_dir_pulses_per_frame(layout) of `count` pulses as a step/dir frame;
/// `sent` tells how many went in. Context: any (pure function).
struct StepDirFrame {
  FrameWords words;
  uint8_t sent = 0;
};
StepDirFrame encode_step_dir_frame(uint32_t count, bool forward, const FrameLayout& layout);

}  // namespace stepdance::protocol
