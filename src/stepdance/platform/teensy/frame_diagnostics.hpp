// Teensy-only counters that show whether the frame pipeline kept up with the hardware frame clock.
#pragma once

#if defined(__IMXRT1062__)

#include <stdint.h>

namespace stepdance::platform::teensy {

/// Frame-clock bookkeeping since boot (each counter wraps at 2^32).
struct FrameDiagnostics {
  uint32_t ticks;                ///< hardware frame ticks seen by the tick ISR
  uint32_t frames;               ///< frame ISRs run (one per tick when the frame keeps up)
  uint32_t ticks_without_frame;  ///< ticks whose frame ISR never ran (the previous one overran)
  uint32_t late_frames;          ///< frames committed after the tick they were due for: dropped,
                                 ///< never sent late and never sent twice
};

/// A snapshot of the counters. Context: any.
FrameDiagnostics frame_diagnostics();

}  // namespace stepdance::platform::teensy

#endif  // __IMXRT1062__
