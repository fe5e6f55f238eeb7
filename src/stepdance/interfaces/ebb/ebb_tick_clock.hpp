// EBB tick clock: the EBB's 40 µs motion tick counted out of frames of any period, stretched when
// a move asks more steps of a channel than its frames carry.
#pragma once

#include <stdint.h>

namespace stepdance::ebb {

/// When the next EBB tick falls: a tick is due once ticks_us × stretch of frame time has passed
/// (every frame at 40 µs, every 4th at 10 µs, 5 ticks in 8 frames at 25 µs). The stretch (≥ 1,
/// kept in Q16) slows a whole move when its fastest motor would need more than one channel step
/// per frame. Context: frame ISR.
class EbbTickClock {
 public:
  /// A stretch of 1 in Q16.
  static constexpr uint32_t kUnstretchedQ16 = 65536;

  /// Counts one frame of `period_us` µs; true when an EBB tick is due in it.
  bool advance(uint32_t period_us);
  /// Sets the stretch for a move whose fastest motor takes `sixteenths_per_tick` 1/16 steps per
  /// 40 µs tick, with frames of `period_us` (one channel step each): 1 when they carry it, else
  /// the ratio rounded up to 1/65536. True when the move is stretched.
  bool fit(double sixteenths_per_tick, uint32_t period_us);
  /// The current move's tick length over 40 µs (≥ 1).
  double stretch() const { return static_cast<double>(stretch_q16_) / kUnstretchedQ16; }
  /// 1/16 steps per tick the frames of `period_us` carry: one per frame.
  static double carried_per_tick(uint32_t period_us);

 private:
  uint32_t time_q16_ = 0;  // frame time not yet spent on a tick, µs·2^16 (< one tick)
  uint32_t stretch_q16_ = kUnstretchedQ16;
};

}  // namespace stepdance::ebb
