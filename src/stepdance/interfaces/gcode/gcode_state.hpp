// The interpreter's modal state and stored coordinate data (what `$G` and `$#` report).
#pragma once

#include <stdint.h>

#include "stepdance/interfaces/gcode/gcode_block.hpp"
#include "stepdance/interfaces/gcode/motion.hpp"

namespace stepdance::gcode {

/// Offsets kept across lines (and, in Grbl, across power cycles): G54–G59, G28, G30. In mm.
struct CoordinateData {
  static constexpr int kSystemCount = 6;  ///< G54 .. G59
  double system_offset_mm[kSystemCount][kOffsetAxisCount] = {};
  double g28_position_mm[kOffsetAxisCount] = {};
  double g30_position_mm[kOffsetAxisCount] = {};
};

/// Modal state after the last accepted line.
struct ModalState {
  CommandCode motion = 0;              ///< 0, 10, 20, 30 or 800 (G80)
  CommandCode plane = 170;             ///< 170, 180, 190
  bool absolute = true;                ///< G90 (true) / G91
  bool inverse_time = false;           ///< G93 (true) / G94
  bool inches = false;                 ///< G20 (true) / G21
  uint8_t coordinate_system = 0;       ///< 0 = G54 .. 5 = G59
  bool extruder_relative = false;      ///< M83 (true) / M82
  CommandCode spindle = 50;            ///< 30, 40 or 50 (M5)
  CommandCode coolant = 90;            ///< 70, 80 or 90 (M9)
  double feed_mm_per_min = 0.0;        ///< F in force (G94); 0 = never set
  double spindle_speed = 0.0;          ///< S in force
  uint8_t tool = 0;                    ///< T in force
  bool tool_length_dynamic = false;    ///< G43.1 (true) / G49
  double tool_length_offset_mm = 0.0;  ///< G43.1's Z offset, added to absolute Z targets
};

}  // namespace stepdance::gcode
