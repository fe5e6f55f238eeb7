// Pen strokes in machine millimetres and the page they are drawn on (shared by the SVG and PNG writers).
#pragma once

#include <vector>

namespace stepdance::sim {

/// A point in machine coordinates, in mm from the machine origin.
struct PointMm {
  double x = 0;
  double y = 0;
};

/// A polyline the pen followed: drawn (pen down) or a pen-up travel move.
struct Stroke {
  std::vector<PointMm> points;
  bool pen_down = true;
};

/// How a drawing is laid out and drawn.
///
/// The page is the machine's travel area plus a margin on every side, with a white background.
/// The machine origin sits at the top-left corner of the travel area; x grows to the right and
/// y grows DOWN the page, as on a plotter seen from above with its home corner top-left (the
/// AxiDraw's convention). Points outside the travel area are drawn where they fall, cut off at
/// the page edge.
struct DrawingStyle {
  double travel_width_mm = 300;   ///< machine x travel
  double travel_height_mm = 218;  ///< machine y travel
  double margin_mm = 10;          ///< white border around the travel area
  double pen_width_mm = 0.5;      ///< black pen-down lines
  bool pen_up_travel = false;     ///< also draw pen-up strokes (thin, grey, dashed)
  double travel_line_width_mm = 0.2;  ///< line width of pen-up strokes
  double travel_dash_mm = 2;          ///< dash and gap length of pen-up strokes

  double page_width_mm() const { return travel_width_mm + 2 * margin_mm; }
  double page_height_mm() const { return travel_height_mm + 2 * margin_mm; }
};

}  // namespace stepdance::sim
