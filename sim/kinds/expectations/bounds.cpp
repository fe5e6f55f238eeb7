// Expectation kind "bounds_mm": bounds_mm = [x_min, y_min, x_max, y_max], tolerance_mm — the
// bounding box of every pen-down stroke, each edge within the tolerance.
#include "kinds/expectations/bounds.hpp"

#include <algorithm>
#include <cmath>

#include "kinds/expectations/expectation_parts.hpp"
#include "models/machine.hpp"

namespace stepdance::sim {
namespace {

/// Four finite numbers with min <= max.
bool read_box(scenario::TableReader& reader, double (&box_mm)[4]) {
  const toml::array* box = reader.array("bounds_mm");
  bool ok = box != nullptr && box->size() == 4;
  for (size_t i = 0; ok && i < 4; ++i) {
    const auto value = (*box)[i].value<double>();
    ok = value.has_value() && std::isfinite(*value);
    if (ok) box_mm[i] = *value;
  }
  ok = ok && box_mm[0] <= box_mm[2] && box_mm[1] <= box_mm[3];
  if (box != nullptr && !ok) {
    reader.error("bounds_mm", "'bounds_mm' must be four numbers [x_min, y_min, x_max, y_max] with min <= max");
  }
  return ok;
}

bool read(ExpectationReading& reading) {
  BoundsCheck check;
  const bool ok = read_box(reading.reader, check.bounds_mm);
  const bool tolerance_ok = read_tolerance(reading, "bounds_mm", check.tolerance_mm);
  reading.settings = check;
  return tolerance_ok && ok;
}

std::string box_text(const double* edges) {
  return "[" + millimetres(edges[0]) + ", " + millimetres(edges[1]) + ", " + millimetres(edges[2]) + ", " +
         millimetres(edges[3]) + "]";
}

ExpectationResult check(const scenario::Expectation& expectation, const FinishedRun& run) {
  const auto& check = settings_of<BoundsCheck>(expectation);
  if (run.machine() == nullptr) return {false, "bounds_mm: the scenario has no machine"};
  double box[4] = {INFINITY, INFINITY, -INFINITY, -INFINITY};
  for (const Polyline& stroke : run.machine()->strokes()) {
    for (const PenPoint& point : stroke) {
      box[0] = std::min(box[0], point.x_mm);
      box[1] = std::min(box[1], point.y_mm);
      box[2] = std::max(box[2], point.x_mm);
      box[3] = std::max(box[3], point.y_mm);
    }
  }
  const std::string what = "pen-down bounds " + box_text(check.bounds_mm) + " mm ± " + millimetres(check.tolerance_mm);
  if (box[0] > box[2]) return {false, what + ": nothing was drawn"};
  bool met = true;
  for (int i = 0; i < 4; ++i) met = met && std::fabs(box[i] - check.bounds_mm[i]) <= check.tolerance_mm;
  return {met, what + ": got " + box_text(box)};
}

}  // namespace

const ExpectationKind& bounds_expectation() {
  static const ExpectationKind kind{"bounds_mm", {"tolerance_mm"}, read, check};
  return kind;
}

}  // namespace stepdance::sim
