// A parsed line planned, checked whole against the travel, then committed to the machine.
#include "stepdance/interfaces/gcode/gcode_interpreter_stage.hpp"

#include "stepdance/interfaces/gcode/travel_check.hpp"

namespace stepdance::gcode {

void InterpreterStage::begin(GrblMachine& machine, const GrblSettings& settings) {
  machine_ = &machine;
  settings_ = &settings;
}

// Plan, check, commit: the whole line is checked against the soft limits before any of it runs (a G28
// with two legs, an arc by its box), so a refused line leaves no partial motion (Grbl's gc_execute_line
// validates a block completely before acting on it). The machine answers the line once it has taken
// every request (GrblMachine::take_line_end); in check mode nothing is asked of it.
void InterpreterStage::take(const GcodeBlock& block, LineAnswer& answer) {
  adopt_position_when_idle();
  LinePlan plan;
  const GrblError error = interpreter_.plan(block, plan);
  if (error != GrblError::kOk) {
    answer.refuse(error);
    return;
  }
  for (int i = 0; i < plan.motion_count; ++i) {
    if (within_travel(*settings_, plan.motions[i])) continue;
    answer.exceed_travel();  // nothing of the line runs
    return;
  }
  interpreter_.commit(plan, check_mode_ ? nullptr : machine_);
  if (check_mode_) {
    answer.taken();
  } else {
    machine_->take_line_end(answer);
  }
}

// The interpreter's position is only refreshed when idle: while moving, the interpreter is ahead of
// the machine (it plans queued lines), and overwriting it would break relative moves.
void InterpreterStage::adopt_position_when_idle() {
  if (machine_->motion_state() != MotionState::kIdle) return;
  double position[kAxisCount];
  machine_->position_mm(position);
  interpreter_.set_position_mm(position);
}

// As Grbl's soft reset: gc_init clears the parser state, but the coordinate data lives in EEPROM there
// and survives it.
void InterpreterStage::restart() {
  const CoordinateData coordinates = interpreter_.coordinate_data();
  interpreter_ = GcodeInterpreter{};
  interpreter_.set_coordinate_data(coordinates);
  check_mode_ = false;
}

}  // namespace stepdance::gcode
