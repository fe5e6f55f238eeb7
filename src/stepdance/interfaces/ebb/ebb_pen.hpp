// EBB pen: the pen-lift servo's settings (SC,4/5/10/11/12) and the servo moves pen commands queue.
#pragma once

#include <stdint.h>

#include "stepdance/interfaces/ebb/ebb_motion.hpp"

namespace stepdance::ebb {

/// The pen as the loop commands it: up and down servo positions and slew rates, and the state
/// the last queued pen command asked for (TP toggles that, not the executed state). Positions
/// are servo pulse widths in 1/12 µs, rates 1/12 µs per 24 ms (0 = at once). Context: loop.
class EbbPen {
 public:
  /// S2's pin for the pen servo: RP4 is RB1, the pen-lift output.
  static constexpr uint8_t kServoPin = 4;

  /// SC,`parameter`,`value` for the pen's parameters (4 up position, 5 down, 10 both rates,
  /// 11 up rate, 12 down rate); false, changing nothing, for any other parameter.
  bool configure(int64_t parameter, uint16_t value);
  /// SP,1 (`up`) or SP,0: to the up or down position at its rate, then `delay_ms` of waiting.
  EbbMove move(bool up, uint32_t delay_ms) const;
  /// S2,`position`,4,`rate`,`delay_ms`: to any position; up when it lies on the up position's
  /// side of the middle between up and down.
  EbbMove position_move(uint16_t position, uint16_t rate, uint32_t delay_ms) const;
  /// Records what a queued pen move asked for (call once it is queued).
  void commanded(bool up) { commanded_up_ = up; }
  /// The pen state the last queued pen command asked for (TP's starting point).
  bool commanded_up() const { return commanded_up_; }
  /// SP,2 and SP,3 (`down_becomes_up`): up at once; SP,3 also makes the down position the up one.
  void lift_now(bool down_becomes_up);
  /// R: the pen counts as up again (the positions and rates stay).
  void reset() { commanded_up_ = true; }

  uint16_t up_position() const { return up_; }
  uint16_t up_rate() const { return rate_up_; }
  uint16_t down_position() const { return down_; }
  uint16_t down_rate() const { return rate_down_; }

  /// A servo pulse width (1/12 µs) as servo-board steps (µs) from neutral 1.5 ms: the z output
  /// before its ratio. Context: any (pure).
  static double steps_from_neutral(double position_twelfths_us);

 private:
  uint16_t up_ = 20000;     // SC,4: 1.667 ms, pen up on an AxiDraw-style lift
  uint16_t down_ = 16000;   // SC,5: 1.333 ms
  uint16_t rate_up_ = 0;    // SC,11 / SC,10
  uint16_t rate_down_ = 0;  // SC,12 / SC,10
  bool commanded_up_ = true;
};

}  // namespace stepdance::ebb
