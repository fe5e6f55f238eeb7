// Encodes one frame's signals into STEP/DIR bit words (pure; runs in the frame ISR).
#pragma once

#include <stdint.h>

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

/// True if every signal in mask fits into one 32 µs frame (sum of width + gap ≤ 31 µs).
/// Context: any.
bool signals_fit(uint8_t mask);

/// Encodes a frame: chooses the signals to send (carried ones first, then by index, each taken
/// if it still fits), then lays them out in index order from 2 µs with 2 µs gaps. A forward
/// signal's DIR is high from 1 µs before its STEP rises to 1 µs after it falls; DIR is low
/// otherwise. Signals that do not fit are returned in carried_mask, never dropped.
/// Context: any (pure function).
EncodedFrame encode_frame(const FrameRequest& request);

}  // namespace stepdance::protocol
