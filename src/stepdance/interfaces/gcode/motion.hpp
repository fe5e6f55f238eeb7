// What the G-code interpreter asks of the machine: motions and actions, in machine millimetres.
#pragma once

#include <stdint.h>

#include "stepdance/interfaces/gcode/gcode_block.hpp"

namespace stepdance::gcode {

/// Axes the interpreter tracks. E is the extruder of 3D-printer files.
enum Axis : uint8_t { kAxisX = 0, kAxisY = 1, kAxisZ = 2, kAxisE = 3 };
constexpr int kAxisCount = 4;
/// Axes that carry coordinate-system offsets (E has only G92).
constexpr int kOffsetAxisCount = 3;

enum class MotionKind : uint8_t {
  kRapid,   ///< G0 (and the moves of G28/G30): at the machine's maximum rate
  kLinear,  ///< G1
  kArc,     ///< G2/G3, to be split into chords by an ArcSegmenter
};

/// One motion in machine coordinates (mm), already validated and with units applied.
struct Motion {
  MotionKind kind = MotionKind::kRapid;
  double start_mm[kAxisCount] = {};
  double end_mm[kAxisCount] = {};
  double feed_mm_per_min = 0.0;  ///< G94 feed; 0 for rapids and inverse-time moves
  double duration_min = 0.0;     ///< G93: the whole motion takes this long; 0 otherwise
  // Arcs only: the plane's two axes, the centre in them, the start radius and the signed sweep
  // (positive counter-clockwise looking down the plane's normal).
  uint8_t plane_axis_0 = kAxisX;
  uint8_t plane_axis_1 = kAxisY;
  uint8_t plane_normal = kAxisZ;
  double center_0_mm = 0.0;
  double center_1_mm = 0.0;
  double radius_mm = 0.0;
  double sweep_rad = 0.0;
};

/// Receives what an executed line asks for, in Grbl's execution order (spindle, coolant, dwell,
/// motions, program flow). Implementations queue the requests; they are called from the loop.
class GcodeSink {
 public:
  /// A validated motion. Context: loop.
  virtual void on_motion(const Motion& motion) = 0;
  /// G4: wait this long once earlier motions are done. Context: loop.
  virtual void on_dwell(double seconds) = 0;
  /// M3 (clockwise), M4 (counter-clockwise) or M5 (stop), with the S speed in force.
  /// Context: loop.
  virtual void on_spindle(CommandCode m_code, double speed) {
    (void)m_code;
    (void)speed;
  }
  /// M7, M8 or M9. Context: loop.
  virtual void on_coolant(CommandCode m_code) { (void)m_code; }
  /// M0, M1, M2 or M30, after the line's motions. Context: loop.
  virtual void on_program_flow(CommandCode m_code) { (void)m_code; }
  /// G10, G28.1 or G30.1 changed stored coordinate data (persist it). Context: loop.
  virtual void on_coordinate_data_changed() {}

 protected:
  ~GcodeSink() = default;
};

}  // namespace stepdance::gcode
