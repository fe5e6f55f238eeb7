// Where a G-code line's outcome goes at the end of its one-way path.
#pragma once

#include "stepdance/interfaces/gcode/grbl_error.hpp"

namespace stepdance::gcode {

/// The end of a G-code line's path (receiver → parser → interpreter → machine's planner): the
/// stage that finishes with the line says so here, once, and nobody hands the line back. A stage
/// that refuses the line calls refuse() or exceed_travel() and hands nothing on; otherwise the
/// machine calls taken() once every request of the line is in its planner (at once for a straight
/// move, after the last chord of an arc, at the end of a dwell). Context: loop.
class LineAnswer {
 public:
  /// The line is refused whole with Grbl's error number; nothing of it ran. Context: loop.
  virtual void refuse(GrblError error) = 0;
  /// A target of the line lies outside the travel with soft limits on; nothing of it ran (the
  /// soft-limit alarm follows, and the reset that ends it answers the line). Context: loop.
  virtual void exceed_travel() = 0;
  /// Everything the line asked for has been taken by the machine: its `ok` is due. Context: loop.
  virtual void taken() = 0;

 protected:
  ~LineAnswer() = default;
};

}  // namespace stepdance::gcode
