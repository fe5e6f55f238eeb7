// Renders pen strokes to a PNG image with cairo.
#pragma once

#include <string>
#include <vector>

#include "output/drawing.hpp"

namespace stepdance::sim {

/// Pixel size of the PNG of a page: round(page mm × px_per_mm) in each direction, at least 1.
struct PngSize {
  int width = 0;
  int height = 0;
};

/// The image size write_png() produces. Throws std::invalid_argument if px_per_mm is not > 0
/// or the image would exceed 32767 px on a side.
PngSize png_size(const DrawingStyle& style, double px_per_mm);

/// Draws the strokes as the SVG writer does (same layout, white background, black pen-down
/// lines with round caps and joins, pen-up strokes grey and dashed under them when enabled),
/// antialiased, at px_per_mm pixels per mm, into an RGB PNG at `path`. Throws
/// std::invalid_argument for a bad size and std::runtime_error("path: …") if writing fails.
void write_png(const std::string& path, const std::vector<Stroke>& strokes, const DrawingStyle& style,
               double px_per_mm);

}  // namespace stepdance::sim
