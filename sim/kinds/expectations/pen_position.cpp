// Expectation kind "pen_mm": pen_mm = [x, y], tolerance_mm — where the machine's pen is at the end.
#include "kinds/expectations/pen_position.hpp"

#include <cmath>

#include "kinds/expectations/expectation_parts.hpp"
#include "models/machine.hpp"

namespace stepdance::sim {
namespace {

bool read(ExpectationReading& reading) {
  const toml::array* pair = reading.reader.array("pen_mm");
  double values[2] = {0, 0};
  const bool ok = pair != nullptr && scenario::read_number_pair(*pair, values);
  if (pair != nullptr && !ok) reading.reader.error("pen_mm", "'pen_mm' must be two numbers [x, y]");
  PenPositionCheck check{values[0], values[1]};
  const bool tolerance_ok = read_tolerance(reading, "pen_mm", check.tolerance_mm);
  reading.settings = check;
  return tolerance_ok && ok;
}

ExpectationResult check(const scenario::Expectation& expectation, const FinishedRun& run) {
  const auto& check = settings_of<PenPositionCheck>(expectation);
  if (run.machine() == nullptr) return {false, "pen_mm: the scenario has no machine"};
  const PenPoint pen = run.machine()->pen_position();
  const double off = std::hypot(pen.x_mm - check.x_mm, pen.y_mm - check.y_mm);
  return {off <= check.tolerance_mm, "pen at [" + millimetres(check.x_mm) + ", " + millimetres(check.y_mm) + "] mm ± " +
                                         millimetres(check.tolerance_mm) + ": got [" + millimetres(pen.x_mm) + ", " +
                                         millimetres(pen.y_mm) + "]"};
}

}  // namespace

const ExpectationKind& pen_position_expectation() {
  static const ExpectationKind kind{"pen_mm", {"tolerance_mm"}, read, check};
  return kind;
}

}  // namespace stepdance::sim
