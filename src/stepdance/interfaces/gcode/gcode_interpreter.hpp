// Executes parsed G-code lines: modal state, offsets and units in, machine-space motions out.
#pragma once

#include "stepdance/interfaces/gcode/gcode_block.hpp"
#include "stepdance/interfaces/gcode/gcode_state.hpp"
#include "stepdance/interfaces/gcode/grbl_error.hpp"
#include "stepdance/interfaces/gcode/motion.hpp"

namespace stepdance::gcode {

/// The G-code interpreter of a Grbl 1.1-style machine. Each line is validated completely before
/// anything changes: a refused line (any GrblError but kOk) leaves the state untouched and asks
/// the sink for nothing. Positions are machine coordinates in mm; work coordinates are machine
/// minus the selected G54–G59 offset minus the G92 offset.
/// Context: loop only (not reentrant; one instance per G-code stream).
class GcodeInterpreter {
 public:
  /// Validates and executes one parsed line, reporting its requests to sink.
  GrblError execute(const GcodeBlock& block, GcodeSink& sink);

  /// Modal state in force.
  const ModalState& modal() const { return modal_; }
  /// Stored coordinate data (G54–G59, G28, G30).
  const CoordinateData& coordinate_data() const { return coordinates_; }
  /// Replaces the stored coordinate data, e.g. after loading it from storage.
  void set_coordinate_data(const CoordinateData& data) { coordinates_ = data; }
  /// G92 offset in mm (X, Y, Z, E).
  const double* g92_offset_mm() const { return g92_offset_mm_; }
  /// Where the interpreter believes the machine is after the last line (mm, machine space).
  const double* position_mm() const { return position_mm_; }
  /// Work coordinate offset in force for an axis (selected system + G92), mm.
  double work_offset_mm(int axis) const;
  /// Adopts a machine position measured elsewhere (after a jog, a reset, homing, live nudges).
  void set_position_mm(const double (&machine_mm)[kAxisCount]);
  /// Grbl's program-end reset of the modal state (M2/M30): G1 G17 G90 G94 G54 M5 M9 (M82).
  void reset_modal_for_program_end();

 private:
  ModalState modal_;
  CoordinateData coordinates_;
  double g92_offset_mm_[kAxisCount] = {};
  double position_mm_[kAxisCount] = {};
};

}  // namespace stepdance::gcode
