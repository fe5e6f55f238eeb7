// Executes parsed G-code lines: modal state, offsets and units in, machine-space motions out.
#pragma once

#include "stepdance/interfaces/gcode/gcode_block.hpp"
#include "stepdance/interfaces/gcode/gcode_state.hpp"
#include "stepdance/interfaces/gcode/grbl_error.hpp"
#include "stepdance/interfaces/gcode/motion.hpp"

namespace stepdance::gcode {

/// Everything a line may change: modes, stored offsets, G92 and the position (mm, machine space).
struct MachineState {
  ModalState modal;
  CoordinateData coordinates;
  double g92_mm[kAxisCount] = {};
  double position_mm[kAxisCount] = {};
};

/// A line validated against the interpreter's state and not yet applied: the state it leaves and
/// what it asks of the machine, in Grbl's order (spindle, coolant, dwell, motions, data, flow).
struct LinePlan {
  static constexpr int kMaxMotions = 2;  ///< G28/G30: the intermediate point, then the stored one
  MachineState next;
  bool spindle = false;
  bool coolant = false;
  bool dwell = false;
  double dwell_s = 0.0;
  Motion motions[kMaxMotions];
  int motion_count = 0;
  bool program_flow = false;
  CommandCode program_flow_code = 0;
  bool coordinates_changed = false;

  /// Forgets the requests of an earlier line (a motion slot is cleared when it is used again).
  void clear_requests() {
    spindle = coolant = dwell = program_flow = coordinates_changed = false;
    dwell_s = 0.0;
    motion_count = 0;
    program_flow_code = 0;
  }
};

/// The G-code interpreter of a Grbl 1.1-style machine. Each line is validated completely before
/// anything changes: a refused line (any GrblError but kOk) leaves the state untouched and asks
/// the sink for nothing. Positions are machine coordinates in mm; work coordinates are machine
/// minus the selected G54–G59 offset minus the G92 offset.
/// Context: loop only (not reentrant; one instance per G-code stream).
class GcodeInterpreter {
 public:
  /// Validates one parsed line against the state in force; on kOk `plan` holds what it would do.
  /// Nothing changes here: a caller may check the plan (the travel) before commit().
  GrblError plan(const GcodeBlock& block, LinePlan& plan) const;
  /// Applies a plan made from the state in force (no other line in between) and hands its
  /// requests to `sink` in order; a null sink applies the state only (check mode).
  void commit(const LinePlan& plan, GcodeSink* sink);
  /// plan() then commit(): validates and executes one line, reporting its requests to sink.
  GrblError execute(const GcodeBlock& block, GcodeSink& sink);

  /// Modal state in force.
  const ModalState& modal() const { return state_.modal; }
  /// Stored coordinate data (G54–G59, G28, G30).
  const CoordinateData& coordinate_data() const { return state_.coordinates; }
  /// Replaces the stored coordinate data, e.g. after loading it from storage.
  void set_coordinate_data(const CoordinateData& data) { state_.coordinates = data; }
  /// G92 offset in mm (X, Y, Z, E).
  const double* g92_offset_mm() const { return state_.g92_mm; }
  /// Where the interpreter believes the machine is after the last line (mm, machine space).
  const double* position_mm() const { return state_.position_mm; }
  /// Work coordinate offset in force for an axis (selected system + G92), mm.
  double work_offset_mm(int axis) const;
  /// Adopts a machine position measured elsewhere (after a jog, a reset, homing, live nudges).
  void set_position_mm(const double (&machine_mm)[kAxisCount]);
  /// Grbl's program-end reset of the modal state (M2/M30): G1 G17 G90 G94 G54 M5 M9 (M82).
  void reset_modal_for_program_end();

 private:
  MachineState state_;
};

}  // namespace stepdance::gcode
