// The sketch-level entry points of the original library: dance_start, dance_loop and metrics.
#pragma once

#include <stdint.h>

#include "stepdance/core/status.hpp"

/// Starts the real-time engine: call at the end of setup(), after every begin().
/// Returns kOk, or why it could not start (a fault recorded during setup). Context: loop.
stepdance::Status dance_start();
/// Runs the loop stage (interfaces, deferred callbacks). Call at the end of loop(). Context: loop.
void dance_loop();
/// Adds a raw function to every frame (before dance_start: ahead of the stages; after: behind).
/// Context: loop.
stepdance::Status add_function_to_frame(void (*function)());
/// Peak frame-ISR load since the last reset, as a fraction of the frame period (0..1+).
/// Context: any.
float stepdance_get_cpu_usage();
/// Mean frame-ISR load since the last reset, as a fraction of the frame. Context: any.
float stepdance_get_average_cpu_usage();
/// Frames that took longer than the frame period since the last reset. Context: any.
uint32_t stepdance_get_frame_overruns();
/// Clears the load statistics. Context: loop.
void stepdance_metrics_reset();

/// Calls a function from loop() at a steady period without blocking.
class LoopDelay {
 public:
  /// Calls function if at least interval_ms passed since its last call. Periods do not drift:
  /// the next deadline is the previous one plus the interval. Context: loop.
  void periodic_call(void (*function)(), uint32_t interval_ms);  // interval ≤ 71 minutes

 private:
  uint32_t last_call_us_ = 0;
  bool started_ = false;
};
