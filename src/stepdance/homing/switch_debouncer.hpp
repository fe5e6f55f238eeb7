// SwitchDebouncer: a switch level accepted only once it has held for a number of samples.
#pragma once

#include <stdint.h>

namespace stepdance {

/// Debounces a sampled switch: a new level is accepted once it has been read `stable_samples`
/// times in a row, so a bounce or glitch shorter than that never changes the output. Remembers
/// a value (a position) captured at the first sample of the run that was accepted.
/// Context: the one context that samples it (frame ISR for homing).
class SwitchDebouncer {
 public:
  /// Samples in a row a new level must hold (at least 1). Context: loop.
  void set_stable_samples(uint32_t samples) { stable_samples_ = samples == 0 ? 1 : samples; }
  /// Forgets history: the level is taken as it is now. Context: as sample().
  void restart(bool level, double value_now) {
    accepted_ = candidate_ = level;
    run_length_ = stable_samples_;
    candidate_value_ = accepted_value_ = value_now;
  }
  /// Takes one sample; `value_now` is remembered if it starts a new run. Returns true when the
  /// accepted level changed with this sample.
  bool sample(bool level, double value_now) {
    if (level != candidate_) {
      candidate_ = level;
      candidate_value_ = value_now;
      run_length_ = 0;
    }
    if (run_length_ < stable_samples_) ++run_length_;
    if (candidate_ == accepted_ || run_length_ < stable_samples_) return false;
    accepted_ = candidate_;
    accepted_value_ = candidate_value_;
    return true;
  }
  /// The debounced level.
  bool level() const { return accepted_; }
  /// The value remembered at the first sample of the accepted level's run.
  double value_at_change() const { return accepted_value_; }

 private:
  uint32_t stable_samples_ = 1;
  uint32_t run_length_ = 0;
  double candidate_value_ = 0;
  double accepted_value_ = 0;
  bool candidate_ = false;
  bool accepted_ = false;
};

}  // namespace stepdance
