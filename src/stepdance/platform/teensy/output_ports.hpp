// Output ports A–D on FlexIO3: claim, stage, commit, and park (the backend-internal side).
//
// A frame computed in the frame ISR after tick k is staged by port_out_frame(), committed to the
// FlexIO buffers when the frame stages end, and launched by the hardware at tick k+1. The tick
// ISR zeroes the buffers right after every launch, so words are never sent twice: a port that
// gets no new words sends an empty frame.
#pragma once

#if defined(__IMXRT1062__)

#include <stdint.h>

namespace stepdance::platform::teensy {

/// Zeroes the buffers of every claimed port (their words were just launched). Context: tick ISR.
void output_ports_disarm();
/// Writes the staged words of this frame into the FlexIO buffers; returns the ports written.
/// Context: frame ISR, tick ISR masked.
uint8_t output_ports_commit_staged();
/// Forgets the staged words of this frame (its slot has passed). Context: frame ISR.
void output_ports_drop_staged();
/// Zeroes the buffers of the ports in `mask`. Context: any.
void output_ports_zero(uint8_t mask);
/// Hands the claimed ports' pads back to FlexIO3 (after a safe state). Context: loop.
void output_ports_attach_pins();
/// Drives the claimed ports' STEP and DIR pins low as plain GPIO outputs. Context: any.
void output_ports_park_pins();

}  // namespace stepdance::platform::teensy

#endif  // __IMXRT1062__
