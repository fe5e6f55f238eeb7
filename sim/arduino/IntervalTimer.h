// Teensy's IntervalTimer on the host: up to four callbacks run periodically in board time.
#pragma once

#include <stdint.h>

/// A periodic interrupt, as on a Teensy 4 (four PIT channels, so at most four run at once).
///
/// On the host a due callback runs at the board's next timer event: every frame tick (40 µs)
/// once dance_start() has run, every kilohertz tick, each loop() entry and after each delay().
/// So a callback may run up to one frame late, never early, and the average rate is exact:
/// each due time is the previous one plus the period, not "now" plus the period. Callbacks run
/// in interrupt context, as on the board (keep them short; the loop waits meanwhile).
class IntervalTimer {
 public:
  using Callback = void (*)();

  IntervalTimer() = default;
  ~IntervalTimer() { end(); }
  // The board's timer table knows each running timer by its address.
  IntervalTimer(const IntervalTimer&) = delete;
  IntervalTimer& operator=(const IntervalTimer&) = delete;

  /// Starts calling `callback` every `period_us` microseconds (≥ 1 µs and ≤ 2^32 − 1 µs; the
  /// first call one period from now). Restarting a running timer replaces its callback and
  /// period. Returns false, starting nothing, for a null callback, a period out of range or
  /// when four other timers are running. Context: loop.
  bool begin(Callback callback, double period_us);
  bool begin(Callback callback, unsigned int period_us) { return begin(callback, static_cast<double>(period_us)); }
  bool begin(Callback callback, int period_us) { return begin(callback, static_cast<double>(period_us)); }
  bool begin(Callback callback, unsigned long period_us) { return begin(callback, static_cast<double>(period_us)); }
  bool begin(Callback callback, long period_us) { return begin(callback, static_cast<double>(period_us)); }
  bool begin(Callback callback, float period_us) { return begin(callback, static_cast<double>(period_us)); }

  /// Changes the period from the next call on (the call already due keeps its time), as
  /// Teensy's update() does. Does nothing if the timer is not running or the period is out of
  /// range. Context: loop or the timer's callback.
  void update(double period_us);

  /// Stops the timer (no more calls). Context: loop.
  void end();

  /// Accepted for compatibility; on the host timers do not preempt each other. Context: loop.
  void priority(uint8_t) {}
};

namespace stepdance::arduino {

/// Runs every IntervalTimer callback that is due at micros() (each as often as it fell due).
/// Called by the backend at its timer events and loop entries (see IntervalTimer). Context: ISR.
void run_interval_timers();

}  // namespace stepdance::arduino
