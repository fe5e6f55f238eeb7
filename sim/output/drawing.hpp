// Pen strokes in machine millimetres and the page they are drawn on (shared by the SVG and PNG writers).
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
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
  /// The machine's measure along this stroke (e.g. filament mm per toolpath mm), if it has one:
  /// the stroke is then coloured by it (see shade_colour) instead of black.
  std::optional<double> shade = std::nullopt;
};

/// An sRGB colour, each channel 0–1.
struct Rgb {
  double r = 0;
  double g = 0;
  double b = 0;
};

/// The colour a fraction u (0–1) of the way from a to b.
inline Rgb mix(const Rgb& a, const Rgb& b, double u) {
  return Rgb{a.r + (b.r - a.r) * u, a.g + (b.g - a.g) * u, a.b + (b.b - a.b) * u};
}

/// The colour scale for shades spanning [low, high]: that range, widened to at least ±25 % of
/// its middle so the measuring noise of an even extrusion stays one colour. {low, high} of the
/// scale; DrawingStyle::shade_low and shade_high take them.
inline std::pair<double, double> shade_scale_for(double low, double high) {
  const double middle = (low + high) / 2;
  const double half = std::max((high - low) / 2, 0.25 * std::fabs(middle));
  return {middle - half, middle + half};
}

/// How a drawing is laid out and drawn.
///
/// The page is the machine's travel area plus a margin on every side, with a white background.
/// The machine origin sits at the top-left corner of the travel area; x grows to the right and
/// y grows DOWN the page, as on a plotter seen from above with its home corner top-left (the
/// AxiDraw's convention). Points outside the travel area are drawn where they fall, cut off at
/// the page edge.
struct DrawingStyle {
  double travel_width_mm = 300;       ///< machine x travel
  double travel_height_mm = 218;      ///< machine y travel
  double margin_mm = 10;              ///< white border around the travel area
  double pen_width_mm = 0.5;          ///< black pen-down lines
  bool pen_up_travel = false;         ///< also draw pen-up strokes (thin, grey, dashed)
  double travel_line_width_mm = 0.2;  ///< line width of pen-up strokes
  double travel_dash_mm = 2;          ///< dash and gap length of pen-up strokes
  /// Shades from shade_low to shade_high run blue → green → red (values outside are clamped);
  /// a range of zero width draws every shaded stroke in the middle colour.
  double shade_low = 0;
  double shade_high = 0;
  /// What the shades measure (written into the SVG's description); empty: no shading.
  std::string shade_name;

  double page_width_mm() const { return travel_width_mm + 2 * margin_mm; }
  double page_height_mm() const { return travel_height_mm + 2 * margin_mm; }
  /// The colour of a stroke: black, or its shade on the blue → green → red scale.
  Rgb colour_of(const Stroke& stroke) const {
    if (!stroke.shade) return Rgb{};
    const double span = shade_high - shade_low;
    double t = span > 0 ? (*stroke.shade - shade_low) / span : 0.5;
    t = t < 0 ? 0 : (t > 1 ? 1 : t);
    // Two straight ramps through a dark green keep every colour readable on white.
    const Rgb low{0, 0, 0.8}, middle{0, 0.6, 0}, high{0.8, 0, 0};
    return t < 0.5 ? mix(low, middle, 2 * t) : mix(middle, high, 2 * t - 1);
  }
};

}  // namespace stepdance::sim
