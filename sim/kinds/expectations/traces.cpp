// Expectation kind "traces": traces = "<five_bar_arm device>", offset_mm = [dx, dy],
// from_point = N, tolerance_mm — the drawing copies the arm's stylus path, both ways.
#include "kinds/expectations/traces.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "kinds/devices/five_bar_arm.hpp"
#include "kinds/expectations/expectation_parts.hpp"
#include "models/five_bar_arm.hpp"
#include "models/machine.hpp"

namespace stepdance::sim {
namespace {

/// from_point: an index into the arm's path_mm (any index >= 0 when the arm is unknown).
bool read_from_point(scenario::TableReader& reader, const scenario::DeviceConfig* device, const FiveBarArmConfig* arm,
                     int64_t& from_point) {
  const auto from = reader.integer("from_point");
  if (!from) return true;
  const int64_t points = arm != nullptr ? static_cast<int64_t>(arm->path_mm.size()) : 0;
  if (*from >= 0 && (device == nullptr || *from < points)) {
    from_point = *from;
    return true;
  }
  reader.error("from_point", "'from_point' must index the arm's path_mm (0.." + std::to_string(points - 1) + "), got " +
                                 std::to_string(*from));
  return false;
}

bool read(ExpectationReading& reading) {
  scenario::TableReader& reader = reading.reader;
  TracesCheck check;
  const auto name = reader.string("traces");
  bool ok = name.has_value();
  const scenario::DeviceConfig* device = name ? reading.context.scenario.device(*name) : nullptr;
  const FiveBarArmConfig* arm = device != nullptr ? device->settings_as<FiveBarArmConfig>() : nullptr;
  if (name && arm == nullptr) {
    reader.error("traces", "'traces' must name a five_bar_arm device, got '" + *name + "'");
    ok = false;
  }
  if (ok) check.arm = *name;
  const toml::array* offset = reader.array("offset_mm");
  if (offset != nullptr && !scenario::read_number_pair(*offset, check.offset_mm)) {
    reader.error("offset_mm", "'offset_mm' must be two numbers [dx, dy]");
    ok = false;
  }
  ok = read_from_point(reader, device, arm, check.from_point) && ok;
  const bool tolerance_ok = read_tolerance(reading, "traces", check.tolerance_mm);
  reading.settings = check;
  return tolerance_ok && ok;
}

/// Distance from p to the segment ab.
double to_segment_mm(const PenPoint& p, const PenPoint& a, const PenPoint& b) {
  const double dx = b.x_mm - a.x_mm, dy = b.y_mm - a.y_mm;
  const double span = dx * dx + dy * dy;
  double k = span > 0 ? ((p.x_mm - a.x_mm) * dx + (p.y_mm - a.y_mm) * dy) / span : 0.0;
  k = std::clamp(k, 0.0, 1.0);
  return std::hypot(p.x_mm - (a.x_mm + k * dx), p.y_mm - (a.y_mm + k * dy));
}

/// Distance from p to the nearest point of any of the polylines (a one-point line is a dot).
double to_polylines_mm(const PenPoint& p, const std::vector<Polyline>& lines) {
  double nearest = INFINITY;
  for (const Polyline& line : lines) {
    if (line.size() == 1) nearest = std::min(nearest, std::hypot(p.x_mm - line[0].x_mm, p.y_mm - line[0].y_mm));
    for (size_t i = 1; i < line.size(); ++i) nearest = std::min(nearest, to_segment_mm(p, line[i - 1], line[i]));
  }
  return nearest;
}

// Both ways: every drawn point lies near the stylus's path, and every path point from
// `from_point` on lies near the drawing — so nothing extra is drawn and nothing is left out.
ExpectationResult check(const scenario::Expectation& expectation, const FinishedRun& run) {
  const auto& check = settings_of<TracesCheck>(expectation);
  const FiveBarArm* arm = model_of<FiveBarArm>(run.device(check.arm));
  if (arm == nullptr || run.machine() == nullptr) return {false, "traces: no such arm or no machine"};
  Polyline path;
  for (const PenPoint& point : arm->path())
    path.push_back({point.x_mm + check.offset_mm[0], point.y_mm + check.offset_mm[1]});
  const std::vector<Polyline>& strokes = run.machine()->strokes();
  double drawn_off = 0;
  for (const Polyline& stroke : strokes) {
    for (const PenPoint& point : stroke) drawn_off = std::max(drawn_off, to_polylines_mm(point, {path}));
  }
  double missed = 0;
  // path[0] is the arm's home; path_mm[i] is path[i + 1].
  for (size_t i = static_cast<size_t>(check.from_point) + 1; i < path.size(); ++i) {
    missed = std::max(missed, to_polylines_mm(path[i], strokes));
  }
  char text[200];
  std::snprintf(text, sizeof text,
                "drawing traces arm '%s' within %.3f mm: farthest drawn point %.4f mm off its path, farthest "
                "path point %.4f mm from the drawing",
                check.arm.c_str(), check.tolerance_mm, drawn_off, missed);
  const bool drew = !strokes.empty();
  return {drew && drawn_off <= check.tolerance_mm && missed <= check.tolerance_mm, text};
}

}  // namespace

const ExpectationKind& traces_expectation() {
  static const ExpectationKind kind{"traces", {"offset_mm", "from_point", "tolerance_mm"}, read, check};
  return kind;
}

}  // namespace stepdance::sim
