// Writes pen strokes as a deterministic, hand-written SVG document in millimetres.
#pragma once

#include <string>
#include <vector>

#include "output/drawing.hpp"

namespace stepdance::sim {

/// The SVG text of a drawing (see DrawingStyle for the layout): one user unit is 1 mm, the page
/// is width×height mm, coordinates have at most 3 decimals. Pen-up strokes (when drawn) come
/// first in a grey dashed group, then pen-down strokes in a black group, each as a <polyline>
/// in input order. A one-point stroke is drawn as a dot. Strokes without points are skipped.
/// The same input always gives the same bytes.
std::string svg_document(const std::vector<Stroke>& strokes, const DrawingStyle& style);

/// Writes svg_document() to `path`. Throws std::runtime_error("path: …") if it cannot.
void write_svg(const std::string& path, const std::vector<Stroke>& strokes, const DrawingStyle& style);

}  // namespace stepdance::sim
