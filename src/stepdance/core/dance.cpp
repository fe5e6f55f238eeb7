// Sketch-level entry points over the engine.
#include "stepdance/core/dance.hpp"

#include "stepdance/core/engine.hpp"
#include "stepdance/hal/hal.hpp"

using stepdance::engine;

stepdance::Status dance_start() { return engine().start(); }

void dance_loop() { engine().run_loop(); }

stepdance::Status add_function_to_frame(void (*function)()) { return engine().add_frame_function(function); }

// The original's CPU-usage calls, as fractions of the frame budget (frame time in cycles over cycles
// per frame period), peak and average.
float stepdance_get_cpu_usage() { return static_cast<float>(engine().load().peak_fraction()); }

float stepdance_get_average_cpu_usage() { return static_cast<float>(engine().load().average_fraction()); }

uint32_t stepdance_get_frame_overruns() { return engine().load().overruns(); }

void stepdance_metrics_reset() { engine().reset_load(); }

// The first call only starts the clock. Later calls keep the schedule (last += interval) so the mean
// rate is exact despite loop jitter, unless the loop fell more than a whole interval behind: then it
// resynchronises instead of firing a burst of catch-up calls.
void LoopDelay::periodic_call(void (*function)(), uint32_t interval_ms) {
  // Microseconds wrap every ~71.6 minutes; unsigned differences stay right across the wrap.
  const uint32_t now_us = stepdance::hal::micros_now();
  const uint32_t interval_us = interval_ms * 1000u;
  if (!started_) {
    started_ = true;
    last_call_us_ = now_us;
    return;
  }
  if (now_us - last_call_us_ < interval_us) return;
  last_call_us_ += interval_us;
  if (now_us - last_call_us_ >= interval_us) last_call_us_ = now_us;  // fell far behind: resync
  if (function != nullptr) function();
}
