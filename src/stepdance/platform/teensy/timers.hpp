// The two timers behind the HAL's frame and kilohertz contexts (backend-internal stops).
#pragma once

#if defined(__IMXRT1062__)

namespace stepdance::platform::teensy {

/// Stops the FlexIO3 frame clock, the tick ISR and the frame ISR. Context: any.
void frame_timer_stop();
/// Stops GPT2 and the kilohertz ISR. Context: any.
void khz_timer_stop();

}  // namespace stepdance::platform::teensy

#endif  // __IMXRT1062__
