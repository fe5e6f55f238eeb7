// Expectation kind "extruded_per_mm": extruded_per_mm = ratio, relative_tolerance (default 0.01)
// — the extruder's advance per mm of pen-down (extruding) path (a cartesian machine with an 'e'
// socket).
#include "kinds/expectations/extrusion_ratio.hpp"

#include <cmath>
#include <cstdio>
#include <optional>

#include "kinds/expectations/expectation_parts.hpp"
#include "kinds/machines/cartesian.hpp"
#include "models/machine.hpp"

namespace stepdance::sim {
namespace {

bool read_relative_tolerance(scenario::TableReader& reader, double& relative_tolerance) {
  const auto tolerance = reader.number("relative_tolerance");
  if (!tolerance) return true;
  if (*tolerance > 0 && *tolerance < 1) {
    relative_tolerance = *tolerance;
    return true;
  }
  reader.error("relative_tolerance",
               "'relative_tolerance' must be in (0, 1), got " + scenario::format_number(*tolerance));
  return false;
}

bool read(ExpectationReading& reading) {
  scenario::TableReader& reader = reading.reader;
  ExtrusionRatioCheck check;
  const auto ratio = reader.number("extruded_per_mm");
  bool ok = ratio.has_value() && std::isfinite(*ratio) && *ratio > 0;
  if (ratio && !ok) {
    reader.error("extruded_per_mm",
                 "'extruded_per_mm' must be a finite number > 0, got " + scenario::format_number(*ratio));
  }
  if (ok) check.extruded_per_mm = *ratio;
  ok = read_relative_tolerance(reader, check.relative_tolerance) && ok;
  const auto& machine = reading.context.scenario.machine;
  const auto* cartesian = machine ? machine->settings_as<CartesianConfig>() : nullptr;
  if (cartesian == nullptr || !cartesian->e) {
    reader.error("extruded_per_mm", "'extruded_per_mm' needs a cartesian [machine] with an 'e' socket");
    ok = false;
  }
  reading.settings = check;
  return ok;
}

double polyline_length_mm(const std::vector<Polyline>& strokes) {
  double length = 0;
  for (const Polyline& stroke : strokes) {
    for (size_t i = 1; i < stroke.size(); ++i) {
      length += std::hypot(stroke[i].x_mm - stroke[i - 1].x_mm, stroke[i].y_mm - stroke[i - 1].y_mm);
    }
  }
  return length;
}

// Both lengths come from the machine's motors: the extruder's advance, and the pen-down
// (extruding) toolpath as stored — polylines that smooth out the axes' stair steps, which would
// otherwise add up to a fifth to a curve's length.
ExpectationResult check(const scenario::Expectation& expectation, const FinishedRun& run) {
  const auto& check = settings_of<ExtrusionRatioCheck>(expectation);
  const std::optional<double> e = run.machine() ? run.machine()->axis_mm(MachineAxis::kE) : std::nullopt;
  if (!e) return {false, "extruded_per_mm: the machine has no extruder"};
  const double path = polyline_length_mm(run.machine()->strokes());
  char text[160];
  std::snprintf(text, sizeof text, "extruded %.4f mm over %.3f mm of path: %.6f per mm (expected %.6f ± %.2f %%)", *e,
                path, path > 0 ? *e / path : 0.0, check.extruded_per_mm, check.relative_tolerance * 100);
  if (path <= 0) return {false, text};
  return {std::fabs(*e / path - check.extruded_per_mm) <= check.relative_tolerance * check.extruded_per_mm, text};
}

}  // namespace

const ExpectationKind& extrusion_ratio_expectation() {
  static const ExpectationKind kind{"extruded_per_mm", {"relative_tolerance"}, read, check};
  return kind;
}

}  // namespace stepdance::sim
