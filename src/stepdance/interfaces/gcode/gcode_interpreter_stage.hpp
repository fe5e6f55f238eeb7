// The interpreter's stage of a G-code line's path: plan, travel check, commit to the machine.
#pragma once

#include "stepdance/interfaces/gcode/gcode_block.hpp"
#include "stepdance/interfaces/gcode/gcode_interpreter.hpp"
#include "stepdance/interfaces/gcode/grbl_machine.hpp"
#include "stepdance/interfaces/gcode/grbl_settings.hpp"
#include "stepdance/interfaces/gcode/line_answer.hpp"

namespace stepdance::gcode {

/// Second stage of a G-code line (after ParserStage): the interpreter plans the parsed block
/// against the state in force (nothing changes yet), the whole plan is checked against the travel,
/// and only then committed, its requests handed forward to the machine, whose planner takes them
/// and answers the line (GrblMachine::take_line_end). A refused line changes nothing and reaches
/// no machine. In check mode (`$C`) the state advances and nothing moves. Context: loop only.
class InterpreterStage {
 public:
  /// Connects the stage; the machine and settings must outlive it. Context: loop.
  void begin(GrblMachine& machine, const GrblSettings& settings);
  /// Takes one parsed, non-empty block: refuses it through `answer`, or hands its requests and
  /// then its end to the machine. Context: loop.
  void take(const GcodeBlock& block, LineAnswer& answer);
  /// Adopts the machine's position when it is at rest (before a line or a jog is planned).
  /// Context: loop.
  void adopt_position_when_idle();

  /// `$C`: lines change the state but ask the machine for nothing. Context: loop.
  void set_check_mode(bool on) { check_mode_ = on; }
  bool check_mode() const { return check_mode_; }
  /// Grbl's soft reset of the parser: modes, G92 and position to power-on; the stored coordinate
  /// data (G54–G59, G28, G30) is kept; check mode ends. Context: loop.
  void restart();

  GcodeInterpreter& interpreter() { return interpreter_; }
  const GcodeInterpreter& interpreter() const { return interpreter_; }

 private:
  GcodeInterpreter interpreter_;
  GrblMachine* machine_ = nullptr;
  const GrblSettings* settings_ = nullptr;
  bool check_mode_ = false;
};

}  // namespace stepdance::gcode
