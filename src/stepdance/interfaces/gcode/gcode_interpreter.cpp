// Line execution in Grbl's order: modes, feed, spindle, dwell, offsets, motion, program flow.
#include "stepdance/interfaces/gcode/gcode_interpreter.hpp"

#include <math.h>

#include "stepdance/interfaces/gcode/arc_geometry.hpp"

namespace stepdance::gcode {
namespace {

constexpr double kMmPerInch = 25.4;
constexpr double kPi = 3.14159265358979323846;
/// Most turns one G2/G3 line may ask for with P (a whole number from 1).
constexpr double kMaxArcTurns = 100000.0;
constexpr char kAxisLetters[kAxisCount] = {'X', 'Y', 'Z', 'E'};

constexpr uint32_t letter_bit(char letter) { return 1u << word_index(letter); }
constexpr uint32_t kAxisWords = letter_bit('X') | letter_bit('Y') | letter_bit('Z') | letter_bit('E');
constexpr uint32_t kOffsetWords = letter_bit('I') | letter_bit('J') | letter_bit('K');

/// Validates one block against a copy of the state and plans its requests.
// One line, executed against a copy of the machine state (plan.next): if any step fails, the line is
// refused whole and the real state is untouched, as Grbl's gc_execute_line validates a block
// completely before acting on it. The steps follow Grbl 1.1's order of execution (the NIST RS274NGC
// order): modes, feed, spindle/tool, dwell, tool length, non-modal commands, motion, program flow.
class LineExecution {
 public:
  LineExecution(const GcodeBlock& block, MachineState& state) : block_(block), state_(state) {}

  GrblError run(LinePlan& plan);

 private:
  void apply_modes();
  GrblError apply_feed();
  GrblError apply_spindle_and_dwell(LinePlan& plan);
  GrblError apply_non_modal(LinePlan& plan);
  GrblError set_coordinate_system(LinePlan& plan);
  void go_to_stored_position(LinePlan& plan, bool g28);
  GrblError set_g92_offset();
  void apply_feed_to_motion(LinePlan& plan, CommandCode mode);
  GrblError apply_tool_length();
  GrblError apply_motion(LinePlan& plan);
  GrblError plan_arc(Motion& motion);
  GrblError apply_arc_turns(Motion& motion);
  void apply_program_flow(LinePlan& plan);

  double unit_mm() const { return state_.modal.inches ? kMmPerInch : 1.0; }
  double axis_mm(int axis) const { return block_.word(kAxisLetters[axis]) * unit_mm(); }
  bool has_axis(int axis) const { return block_.has_word(kAxisLetters[axis]); }
  double system_offset_mm(int axis) const {
    return axis < kOffsetAxisCount ? state_.coordinates.system_offset_mm[state_.modal.coordinate_system][axis] : 0.0;
  }
  /// G43.1's offset on Z, as Grbl adds it to absolute targets and work offsets (G10 L20, G92).
  double tool_length_mm(int axis) const { return axis == kAxisZ ? state_.modal.tool_length_offset_mm : 0.0; }
  void use(uint32_t letters) { used_words_ |= (block_.words_present & letters); }
  void target_mm(bool machine_coordinates, double (&out)[kAxisCount]) const;
  Motion& add_motion(LinePlan& plan, MotionKind kind, const double (&end)[kAxisCount]);

  const GcodeBlock& block_;
  MachineState& state_;
  uint32_t used_words_ = 0;
  bool axis_words_taken_ = false;  // a non-modal command (G10, G28, G30, G92) owns them
  double inverse_time_f_ = 0.0;
};

// Leaving G93 (inverse time) clears the feed rate, as in Grbl: an F given as 1/minutes must not be
// reused as mm/min. G54…G59 are stored as 0…5 (code 540 + 10 per system).
void LineExecution::apply_modes() {
  if (block_.has_g(GGroup::kFeedMode)) {
    const bool was_inverse = state_.modal.inverse_time;
    state_.modal.inverse_time = block_.g_code(GGroup::kFeedMode) == 930;
    if (was_inverse && !state_.modal.inverse_time) state_.modal.feed_mm_per_min = 0.0;
  }
  if (block_.has_g(GGroup::kUnits)) state_.modal.inches = block_.g_code(GGroup::kUnits) == 200;
  if (block_.has_g(GGroup::kPlane)) state_.modal.plane = block_.g_code(GGroup::kPlane);
  if (block_.has_g(GGroup::kCoordSystem)) {
    state_.modal.coordinate_system = static_cast<uint8_t>((block_.g_code(GGroup::kCoordSystem) - 540) / 10);
  }
  if (block_.has_g(GGroup::kDistance)) state_.modal.absolute = block_.g_code(GGroup::kDistance) == 900;
  if (block_.has_m(MGroup::kExtruder)) state_.modal.extruder_relative = block_.m_code(MGroup::kExtruder) == 830;
  use(letter_bit('N'));
}

// Under G93 the F word is this line's inverse time (1/minutes, not modal); otherwise the modal feed,
// converted to mm/min under G20.
GrblError LineExecution::apply_feed() {
  if (!block_.has_word('F')) return GrblError::kOk;
  use(letter_bit('F'));
  if (state_.modal.inverse_time) {
    inverse_time_f_ = block_.word('F');
  } else {
    state_.modal.feed_mm_per_min = block_.word('F') * unit_mm();
  }
  return GrblError::kOk;
}

// G4 requires P (seconds, as Grbl 1.1; error:28 without it).
GrblError LineExecution::apply_spindle_and_dwell(LinePlan& plan) {
  if (block_.has_word('S')) state_.modal.spindle_speed = block_.word('S');
  if (block_.has_word('T')) state_.modal.tool = static_cast<uint8_t>(block_.word('T'));
  use(letter_bit('S') | letter_bit('T'));
  if (block_.has_m(MGroup::kSpindle)) {
    state_.modal.spindle = block_.m_code(MGroup::kSpindle);
    plan.spindle = true;
  }
  if (block_.has_m(MGroup::kCoolant)) {
    state_.modal.coolant = block_.m_code(MGroup::kCoolant);
    plan.coolant = true;
  }
  if (block_.has_g(GGroup::kNonModal) && block_.g_code(GGroup::kNonModal) == 40) {
    if (!block_.has_word('P')) return GrblError::kValueWordMissing;
    use(letter_bit('P'));
    plan.dwell = true;
    plan.dwell_s = block_.word('P');
  }
  return GrblError::kOk;
}

// Machine-coordinate targets of the line's axis words. Absolute: word + work offset (G54…) + G92 +
// tool length on Z; relative (G91): added to the current position; G53: the word itself (not for E).
// E may be relative under M83 while XYZ stay absolute (the printer convention).
void LineExecution::target_mm(bool machine_coordinates, double (&out)[kAxisCount]) const {
  for (int axis = 0; axis < kAxisCount; ++axis) {
    out[axis] = state_.position_mm[axis];
    if (!has_axis(axis)) continue;
    const bool relative =
        axis == kAxisE ? (state_.modal.extruder_relative || !state_.modal.absolute) : !state_.modal.absolute;
    if (machine_coordinates && axis != kAxisE) {
      out[axis] = axis_mm(axis);
    } else if (relative) {
      out[axis] = state_.position_mm[axis] + axis_mm(axis);
    } else {
      out[axis] = axis_mm(axis) + system_offset_mm(axis) + state_.g92_mm[axis] + tool_length_mm(axis);
    }
  }
}

// Advances the planned position as it records the motion, so a later motion of the same line (G28's
// second leg) starts where this one ends.
Motion& LineExecution::add_motion(LinePlan& plan, MotionKind kind, const double (&end)[kAxisCount]) {
  Motion& motion = plan.motions[plan.motion_count++];
  motion = Motion{};
  motion.kind = kind;
  for (int axis = 0; axis < kAxisCount; ++axis) {
    motion.start_mm[axis] = state_.position_mm[axis];
    motion.end_mm[axis] = end[axis];
    state_.position_mm[axis] = end[axis];
  }
  return motion;
}

// G10, G28, G30 and G92 use the axis words themselves, so a motion command beside them would fight for
// them: error:24 as in Grbl (G80 is allowed, it is no motion).
GrblError LineExecution::apply_non_modal(LinePlan& plan) {
  if (!block_.has_g(GGroup::kNonModal)) return GrblError::kOk;
  const CommandCode code = block_.g_code(GGroup::kNonModal);
  const bool owns_axes = code == 100 || code == 280 || code == 300 || code == 920;
  if (owns_axes && block_.has_g(GGroup::kMotion) && block_.g_code(GGroup::kMotion) != 800) {
    return GrblError::kAxisCommandConflict;
  }
  axis_words_taken_ = owns_axes;
  if (owns_axes) use(kAxisWords);
  switch (code) {
    case 100: return set_coordinate_system(plan);
    case 280:
    case 300: go_to_stored_position(plan, code == 280); break;
    case 281:
    case 301: {  // G28.1 / G30.1: remember the current position
      double* stored = code == 281 ? state_.coordinates.g28_position_mm : state_.coordinates.g30_position_mm;
      for (int axis = 0; axis < kOffsetAxisCount; ++axis) stored[axis] = state_.position_mm[axis];
      plan.coordinates_changed = true;
      break;
    }
    case 920: return set_g92_offset();
    case 921:  // G92.1
      for (double& offset : state_.g92_mm) offset = 0.0;
      break;
    default:  // G4 (handled with the dwell), G53 (with the motion)
      break;
  }
  return GrblError::kOk;
}

// G10 L2 / L20: set a coordinate system's offset (L2: the value; L20: so the current position
// reads the value).
// P0 is the system in use, P1…P6 G54…G59 (Grbl's G10 rules: error:28 without L or P, error:20 for
// another L, error:29 for a P beyond the systems).
GrblError LineExecution::set_coordinate_system(LinePlan& plan) {
  if (!block_.has_word('L') || !block_.has_word('P')) return GrblError::kValueWordMissing;
  use(letter_bit('L') | letter_bit('P'));
  const double l = block_.word('L');
  const double p = block_.word('P');
  if (l != 2.0 && l != 20.0) return GrblError::kUnsupportedCommand;
  if (p != floor(p)) return GrblError::kCommandNeedsInteger;
  if (p > CoordinateData::kSystemCount) return GrblError::kUnsupportedCoordinateSystem;
  if ((block_.words_present & kAxisWords) == 0) return GrblError::kNoAxisWords;
  const int system = p == 0.0 ? state_.modal.coordinate_system : static_cast<int>(p) - 1;
  for (int axis = 0; axis < kOffsetAxisCount; ++axis) {
    if (!has_axis(axis)) continue;
    double& offset = state_.coordinates.system_offset_mm[system][axis];
    offset = (l == 2.0) ? axis_mm(axis)
                        : state_.position_mm[axis] - state_.g92_mm[axis] - axis_mm(axis) - tool_length_mm(axis);
  }
  plan.coordinates_changed = true;
  return GrblError::kOk;
}

// G28 / G30: rapid through the optional intermediate point to the stored one.
void LineExecution::go_to_stored_position(LinePlan& plan, bool g28) {
  double end[kAxisCount];
  if ((block_.words_present & kAxisWords) != 0) {
    target_mm(false, end);
    add_motion(plan, MotionKind::kRapid, end);
  }
  const double* stored = g28 ? state_.coordinates.g28_position_mm : state_.coordinates.g30_position_mm;
  for (int axis = 0; axis < kAxisCount; ++axis) end[axis] = state_.position_mm[axis];
  for (int axis = 0; axis < kOffsetAxisCount; ++axis) end[axis] = stored[axis];
  add_motion(plan, MotionKind::kRapid, end);
}

// G92: the current position becomes the given work coordinates.
GrblError LineExecution::set_g92_offset() {
  if ((block_.words_present & kAxisWords) == 0) return GrblError::kNoAxisWords;
  for (int axis = 0; axis < kAxisCount; ++axis) {
    if (!has_axis(axis)) continue;
    state_.g92_mm[axis] = state_.position_mm[axis] - system_offset_mm(axis) - axis_mm(axis) - tool_length_mm(axis);
  }
  return GrblError::kOk;
}

// G43.1 Z<offset> / G49, as Grbl 1.1: an axis command of its own (no motion or G10/G28/G30/G92
// beside it: error:24), G43.1 with exactly the Z word (error:37 otherwise).
GrblError LineExecution::apply_tool_length() {
  if (!block_.has_g(GGroup::kToolLength)) return GrblError::kOk;
  const bool motion = block_.has_g(GGroup::kMotion) && block_.g_code(GGroup::kMotion) != 800;
  const CommandCode non_modal = block_.has_g(GGroup::kNonModal) ? block_.g_code(GGroup::kNonModal) : 0;
  const bool axis_command = non_modal == 100 || non_modal == 280 || non_modal == 300 || non_modal == 920;
  if (motion || axis_command) return GrblError::kAxisCommandConflict;
  axis_words_taken_ = true;
  state_.modal.tool_length_dynamic = block_.g_code(GGroup::kToolLength) == 431;
  if (!state_.modal.tool_length_dynamic) {
    state_.modal.tool_length_offset_mm = 0.0;
    return GrblError::kOk;
  }
  if ((block_.words_present & kAxisWords) != letter_bit('Z')) return GrblError::kG43DynamicAxisError;
  use(letter_bit('Z'));
  state_.modal.tool_length_offset_mm = axis_mm(kAxisZ);
  return GrblError::kOk;
}

// The plane's two axes come from G17 (XY), G18 (ZX), G19 (YZ); the third is the helix axis. Radius
// form (R) or centre-offset form (I/J/K) as in Grbl; an arc needs an end word in the plane (error:32)
// and, in offset form, an offset in the plane (error:35).
GrblError LineExecution::plan_arc(Motion& motion) {
  const CommandCode plane = state_.modal.plane;
  motion.plane_axis_0 = plane == 170 ? kAxisX : (plane == 180 ? kAxisZ : kAxisY);
  motion.plane_axis_1 = plane == 170 ? kAxisY : (plane == 180 ? kAxisX : kAxisZ);
  motion.plane_normal = plane == 170 ? kAxisZ : (plane == 180 ? kAxisY : kAxisX);
  const char offset_letters[3] = {'I', 'J', 'K'};
  if (!has_axis(motion.plane_axis_0) && !has_axis(motion.plane_axis_1)) return GrblError::kNoInPlaneAxisWords;
  const bool clockwise = state_.modal.motion == 20;
  GrblError error = GrblError::kOk;
  if (block_.has_word('R')) {
    use(letter_bit('R'));
    error = complete_arc_radius(motion, clockwise, block_.word('R') * unit_mm());
  } else {
    const char letter_0 = offset_letters[motion.plane_axis_0];
    const char letter_1 = offset_letters[motion.plane_axis_1];
    if (!block_.has_word(letter_0) && !block_.has_word(letter_1)) return GrblError::kNoInPlaneOffsetWords;
    use(kOffsetWords);  // as Grbl's gcode.c: I, J and K together, the out-of-plane one ignored
    error = complete_arc_ijk(motion, clockwise, block_.word(letter_0) * unit_mm(), block_.word(letter_1) * unit_mm());
  }
  return error == GrblError::kOk ? apply_arc_turns(motion) : error;
}

// P on a G2/G3 line is LinuxCNC's turn count (P1 is the plain arc, each more adds a full turn).
// Grbl refuses such a line (error:36), so no line Grbl accepts changes meaning; a P that G4 took
// stays the dwell's.
GrblError LineExecution::apply_arc_turns(Motion& motion) {
  if (!block_.has_word('P') || (used_words_ & letter_bit('P')) != 0) return GrblError::kOk;
  const double turns = block_.word('P');
  if (turns != floor(turns) || turns < 1.0 || turns > kMaxArcTurns) return GrblError::kCommandNeedsInteger;
  use(letter_bit('P'));
  const double extra_rad = 2.0 * kPi * (turns - 1.0);
  motion.sweep_rad += motion.sweep_rad < 0.0 ? -extra_rad : extra_rad;
  return GrblError::kOk;
}

// Grbl's motion checks in Grbl's order: G53 only with G0/G1 (error:30), axis words with G80 are
// error:31, feed motions need a feed (error:22), arcs need axis words (error:26). Axis words without a
// motion command on the line use the modal motion, as in every G-code dialect.
GrblError LineExecution::apply_motion(LinePlan& plan) {
  if (block_.has_g(GGroup::kMotion)) state_.modal.motion = block_.g_code(GGroup::kMotion);
  const bool absolute_override = block_.has_g(GGroup::kNonModal) && block_.g_code(GGroup::kNonModal) == 530;
  const CommandCode mode = state_.modal.motion;
  if (absolute_override && mode != 0 && mode != 10) return GrblError::kG53NeedsG0OrG1;
  const bool has_axes = (block_.words_present & kAxisWords) != 0;
  const bool explicit_motion = block_.has_g(GGroup::kMotion) && mode != 800;
  if (axis_words_taken_ || (!has_axes && !explicit_motion)) return GrblError::kOk;
  if (mode == 800) return has_axes ? GrblError::kAxisWordsUnused : GrblError::kOk;
  use(kAxisWords);
  if (mode != 0) {
    const bool feed_missing = state_.modal.inverse_time ? !block_.has_word('F') || inverse_time_f_ <= 0.0
                                                        : state_.modal.feed_mm_per_min <= 0.0;
    if (feed_missing) return GrblError::kUndefinedFeedRate;
  }
  if ((mode == 20 || mode == 30) && !has_axes) return GrblError::kNoAxisWords;  // Grbl: before error:32
  if (mode == 20 || mode == 30) {
    double end[kAxisCount];
    target_mm(false, end);
    Motion arc;
    arc.kind = MotionKind::kArc;
    for (int axis = 0; axis < kAxisCount; ++axis) {
      arc.start_mm[axis] = state_.position_mm[axis];
      arc.end_mm[axis] = end[axis];
    }
    const GrblError error = plan_arc(arc);
    if (error != GrblError::kOk) return error;
    Motion& motion = add_motion(plan, MotionKind::kArc, end);
    motion = arc;
  } else if (has_axes) {
    double end[kAxisCount];
    target_mm(absolute_override, end);
    add_motion(plan, mode == 0 ? MotionKind::kRapid : MotionKind::kLinear, end);
  }
  apply_feed_to_motion(plan, mode);
  return GrblError::kOk;
}

// A feed motion (G1, G2, G3) takes the feed in force, or under G93 its duration.
void LineExecution::apply_feed_to_motion(LinePlan& plan, CommandCode mode) {
  if (plan.motion_count == 0 || mode == 0) return;
  Motion& motion = plan.motions[plan.motion_count - 1];
  if (state_.modal.inverse_time) {
    motion.duration_min = 1.0 / inverse_time_f_;
  } else {
    motion.feed_mm_per_min = state_.modal.feed_mm_per_min;
  }
}

void LineExecution::apply_program_flow(LinePlan& plan) {
  if (!block_.has_m(MGroup::kStopping)) return;
  plan.program_flow = true;
  plan.program_flow_code = block_.m_code(MGroup::kStopping);
}

// A word that no command used is an error, not ignored (Grbl: error:31 for axis words, error:36 for
// others), so a typo such as "G1 X10 Q5" never runs half understood. A printer housekeeping code is
// not in the block (the parser left it and its parameters out), so the rest of its line runs.
GrblError LineExecution::run(LinePlan& plan) {
  apply_modes();
  GrblError error = apply_feed();
  if (error == GrblError::kOk) error = apply_spindle_and_dwell(plan);
  if (error == GrblError::kOk) error = apply_tool_length();
  if (error == GrblError::kOk) error = apply_non_modal(plan);
  if (error == GrblError::kOk) error = apply_motion(plan);
  if (error != GrblError::kOk) return error;
  if ((block_.words_present & ~used_words_) != 0) {
    const bool only_axes_left = ((block_.words_present & ~used_words_) & ~kAxisWords) == 0;
    return only_axes_left ? GrblError::kAxisWordsUnused : GrblError::kUnusedValueWords;
  }
  apply_program_flow(plan);
  return GrblError::kOk;
}

}  // namespace

// Loop context. Does not change the interpreter: the caller checks the plan (soft limits) and then
// commit()s it, or drops it.
GrblError GcodeInterpreter::plan(const GcodeBlock& block, LinePlan& plan) const {
  plan.clear_requests();
  plan.next = state_;
  LineExecution line(block, plan.next);
  return line.run(plan);
}

// A null sink is Grbl's check mode ($C): the state advances, nothing moves. M2/M30 reset the modes to
// Grbl's program-end defaults (G1, G17, G90, G94, G54, M5, M9).
void GcodeInterpreter::commit(const LinePlan& plan, GcodeSink* sink) {
  state_ = plan.next;
  const bool program_end = plan.program_flow && (plan.program_flow_code == 20 || plan.program_flow_code == 300);
  if (program_end) reset_modal_for_program_end();
  if (sink == nullptr) return;
  if (plan.spindle) sink->on_spindle(plan.next.modal.spindle, plan.next.modal.spindle_speed);
  if (plan.coolant) sink->on_coolant(plan.next.modal.coolant);
  if (plan.dwell) sink->on_dwell(plan.dwell_s);
  for (int i = 0; i < plan.motion_count; ++i) sink->on_motion(plan.motions[i]);
  if (plan.coordinates_changed) sink->on_coordinate_data_changed();
  if (plan.program_flow) sink->on_program_flow(plan.program_flow_code);
}

GrblError GcodeInterpreter::execute(const GcodeBlock& block, GcodeSink& sink) {
  LinePlan line;
  const GrblError error = plan(block, line);
  if (error == GrblError::kOk) commit(line, &sink);
  return error;
}

double GcodeInterpreter::work_offset_mm(int axis) const {
  const double system =
      axis < kOffsetAxisCount ? state_.coordinates.system_offset_mm[state_.modal.coordinate_system][axis] : 0.0;
  const double tool_length = axis == kAxisZ ? state_.modal.tool_length_offset_mm : 0.0;
  return system + state_.g92_mm[axis] + tool_length;
}

// Only when the machine is idle (InterpreterStage::adopt_position_when_idle): something else may have moved
// the axes between programs (a knob, homing), and the next line must start from where they are.
void GcodeInterpreter::set_position_mm(const double (&machine_mm)[kAxisCount]) {
  for (int axis = 0; axis < kAxisCount; ++axis) state_.position_mm[axis] = machine_mm[axis];
}

void GcodeInterpreter::reset_modal_for_program_end() {
  ModalState& modal = state_.modal;
  modal.motion = 10;
  modal.plane = 170;
  modal.absolute = true;
  modal.inverse_time = false;
  modal.coordinate_system = 0;
  modal.spindle = 50;
  modal.coolant = 90;
  modal.extruder_relative = false;
}

}  // namespace stepdance::gcode
