// The two timers behind the HAL's frame and kilohertz contexts (backend-internal stops).
#pragma once

#if defined(__IMXRT1062__)

#include <stdint.h>

namespace stepdance::platform::teensy {

/// Stops the FlexIO3 frame clock, the tick ISR and the frame ISR. Context: any.
void frame_timer_stop();
/// Stops GPT2 and the kilohertz ISR. Context: any.
void khz_timer_stop();

/// The input sample clock (sample_clock.cpp): PIT channel 3, whose expiries pulse the ENC
/// TRIGGER inputs (XBAR1 input 56 + channel) once a frame, 2 µs before each frame tick.
constexpr unsigned kSampleClockPitChannel = 3;
/// Claims the channel for frames of `period_us` and arms it to start at the next tick; false (and
/// a log line) if PERCLK is not whole MHz or a sketch holds the channel. Context: loop, before the
/// frame clock starts.
bool sample_clock_arm(uint32_t period_us);
/// Starts an armed channel, phase-locked to the tick that just came. Context: the tick ISR.
void sample_clock_on_tick();
/// True once the channel has expired: the ENC hold registers carry the last sample. Context: any.
bool sample_clock_sampled();
/// Stops the channel and gives it back. Context: any.
void sample_clock_stop();

}  // namespace stepdance::platform::teensy

#endif  // __IMXRT1062__
