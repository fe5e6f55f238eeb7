// What the Grbl protocol needs of the machine behind it (GCodeInterface implements it on a TBI).
#pragma once

#include <stdint.h>

#include "stepdance/interfaces/gcode/grbl_error.hpp"
#include "stepdance/interfaces/gcode/line_answer.hpp"
#include "stepdance/interfaces/gcode/motion.hpp"

namespace stepdance::gcode {

/// The machine's motion state, as Grbl's status report names it.
enum class MotionState : uint8_t {
  kIdle,     ///< nothing queued, nothing moving
  kRun,      ///< executing queued motion
  kHolding,  ///< feed hold: decelerating (Hold:1) or stopped (see hold_complete)
  kJog,      ///< executing a jog
};

/// Motion side of a Grbl link, the last stage of a G-code line's path (its planner). Motions and
/// actions arrive through GcodeSink in program order, then the line's end (take_line_end);
/// ready_for_line() says whether the largest request one line can make (two motions, an arc
/// among them, and an action) fits now. All calls come from the loop.
class GrblMachine : public GcodeSink {
 public:
  virtual MotionState motion_state() = 0;
  /// True once a feed hold has come to rest.
  virtual bool hold_complete() = 0;
  /// Position of the G-code stream's own axes (machine coordinates, mm).
  virtual void position_mm(double (&out)[kAxisCount]) = 0;
  /// Speed along the path right now, mm/min.
  virtual double feed_now_mm_per_min() = 0;
  /// Free slots in the motion queue (the first number of `Bf:`).
  virtual uint16_t queue_slots_free() = 0;
  /// Total slots of the motion queue (reported by `$I`).
  virtual uint16_t queue_slots_total() = 0;
  /// Room for one more line's requests.
  virtual bool ready_for_line() = 0;
  /// Ends a line whose requests were all handed over (on_motion, on_dwell…): the machine calls
  /// answer.taken() once its planner has taken every one of them, at once or on a later loop pass
  /// (an arc's chords fed across passes, a dwell's time), as Grbl answers an arc only once all of
  /// it is planned. The default takes everything at once. Context: loop.
  virtual void take_line_end(LineAnswer& answer) { answer.taken(); }

  /// `!`: decelerate to a stop within the acceleration limits, keep the queue.
  virtual void feed_hold() = 0;
  /// `~`: resume after a hold, from exactly where it stopped.
  virtual void cycle_start() = 0;
  /// Ctrl-X: stop at once and flush everything queued. Returns true if motion was under way
  /// (the position may be lost, so the protocol raises an alarm).
  virtual bool soft_reset() = 0;
  /// `$J=` motion (a linear move at its own feed), in machine coordinates.
  virtual void jog(const Motion& motion) = 0;
  /// 0x85: stop jogging with deceleration and drop the queued jog motions.
  virtual void jog_cancel() = 0;
  /// Feed and rapid overrides in percent (feed 10–200, rapid 25/50/100).
  virtual void set_overrides(uint8_t feed_percent, uint8_t rapid_percent) = 0;
  /// `$H`. kHomingDisabled until the sketch configures homing. Context: loop.
  virtual GrblError home() { return GrblError::kHomingDisabled; }
  /// True from a successful home() until the routine has ended (the `$H` line is answered then).
  /// Context: loop.
  virtual bool homing_in_progress() { return false; }
  /// Whether the last routine ended with every axis homed (false: it timed out or faulted).
  /// Context: loop.
  virtual bool homing_succeeded() { return true; }
  /// Steps per mm of an axis's channel (the sketch sets them; `$100`–`$102` report them).
  virtual double steps_per_mm(int axis) = 0;

 protected:
  ~GrblMachine() = default;
};

}  // namespace stepdance::gcode
