// Renders pen strokes to a PNG image with cairo (the PNG module, not in the simulator library).
#pragma once

#include <string>
#include <vector>

#include "output/drawing.hpp"
#include "output/png_page.hpp"

namespace stepdance::sim {

/// Draws the strokes as the SVG writer does (same layout, white background, black pen-down
/// lines with round caps and joins, pen-up strokes grey and dashed under them when enabled),
/// antialiased, at px_per_mm pixels per mm, into an RGB PNG at `path`. Throws
/// std::invalid_argument for a bad size and std::runtime_error("path: …") if writing fails.
void write_png(const std::string& path, const std::vector<Stroke>& strokes, const DrawingStyle& style,
               double px_per_mm);

}  // namespace stepdance::sim
