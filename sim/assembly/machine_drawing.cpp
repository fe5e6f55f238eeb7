// machine_drawing(): the strokes, their shades and the page.
#include "assembly/machine_drawing.hpp"

#include <algorithm>
#include <limits>
#include <optional>
#include <tuple>

#include "kinds/machine_kind.hpp"

namespace stepdance::sim {
namespace {

Stroke stroke_of(const Polyline& line, size_t from, size_t to, bool pen_down) {
  Stroke stroke;
  stroke.pen_down = pen_down;
  for (size_t i = from; i < to; ++i) stroke.points.push_back({line[i].x_mm, line[i].y_mm});
  return stroke;
}

// A pen-down polyline as one stroke per shade: each piece runs from its mark to the next one's
// point, so the pieces join.
void add_shaded(std::vector<Stroke>& strokes, const Polyline& line, const std::vector<ShadeMark>& marks) {
  if (marks.empty()) {
    strokes.push_back(stroke_of(line, 0, line.size(), true));
    return;
  }
  for (size_t i = 0; i < marks.size(); ++i) {
    const size_t end = i + 1 < marks.size() ? marks[i + 1].from_point + 1 : line.size();
    strokes.push_back(stroke_of(line, marks[i].from_point, end, true));
    strokes.back().shade = marks[i].shade;
  }
}

std::vector<Stroke> strokes_of(const Machine& machine) {
  std::vector<Stroke> strokes;
  for (const Polyline& line : machine.pen_up_moves()) strokes.push_back(stroke_of(line, 0, line.size(), false));
  const std::vector<Polyline>& lines = machine.strokes();
  const std::vector<std::vector<ShadeMark>>& marks = machine.shade_marks();
  for (size_t i = 0; i < lines.size(); ++i)
    add_shaded(strokes, lines[i], i < marks.size() ? marks[i] : std::vector<ShadeMark>{});
  return strokes;
}

// The colour scale spans the drawing's shades, and at least ±25 % around their middle, so the
// measuring noise of an even extrusion stays one colour.
void set_shade_scale(DrawingStyle& style, const std::vector<Stroke>& strokes) {
  double low = std::numeric_limits<double>::max(), high = -low;
  for (const Stroke& stroke : strokes) {
    if (stroke.shade) low = std::min(low, *stroke.shade), high = std::max(high, *stroke.shade);
  }
  if (low > high) return;
  std::tie(style.shade_low, style.shade_high) = shade_scale_for(low, high);
}

// A machine with a fixed page (a CoreXY plotter's travel area) draws on it. Other machines have
// none: their page is the drawing's bounding box, moved so it starts at the page origin.
DrawingStyle page_for(const scenario::MachineConfig& machine, std::vector<Stroke>& strokes) {
  DrawingStyle style;
  if (const std::optional<TravelArea> area = machine.kind->page ? machine.kind->page(machine) : std::nullopt) {
    style.travel_width_mm = area->x_max_mm - area->x_min_mm;
    style.travel_height_mm = area->y_max_mm - area->y_min_mm;
    return style;
  }
  double min_x = std::numeric_limits<double>::max(), min_y = min_x, max_x = -min_x, max_y = -min_x;
  for (const Stroke& stroke : strokes) {
    for (const PointMm& point : stroke.points) {
      min_x = std::min(min_x, point.x), max_x = std::max(max_x, point.x);
      min_y = std::min(min_y, point.y), max_y = std::max(max_y, point.y);
    }
  }
  if (min_x > max_x) min_x = max_x = min_y = max_y = 0;
  for (Stroke& stroke : strokes) {
    for (PointMm& point : stroke.points) point = {point.x - min_x, point.y - min_y};
  }
  style.travel_width_mm = std::max(max_x - min_x, 10.0);
  style.travel_height_mm = std::max(max_y - min_y, 10.0);
  return style;
}

}  // namespace

DrawingStyle machine_drawing(const Machine& machine, const scenario::MachineConfig& config, bool pen_up_travel,
                             std::vector<Stroke>& strokes) {
  strokes = strokes_of(machine);
  DrawingStyle style = page_for(config, strokes);
  style.pen_up_travel = pen_up_travel;
  set_shade_scale(style, strokes);
  style.shade_name = machine.shade_name();
  return style;
}

}  // namespace stepdance::sim
