// Expectation kind "drawn_mm": drawn_mm = length, tolerance_mm — the total pen-down path length.
#include "kinds/expectations/drawn_length.hpp"

#include <cmath>

#include "kinds/expectations/expectation_parts.hpp"
#include "models/machine.hpp"

namespace stepdance::sim {
namespace {

bool read(ExpectationReading& reading) {
  DrawnLengthCheck check;
  const auto length = reading.reader.number("drawn_mm");
  bool ok = length.has_value();
  if (length && (!std::isfinite(*length) || *length < 0)) {
    reading.reader.error("drawn_mm",
                         "'drawn_mm' must be a finite length >= 0, got " + scenario::format_number(*length));
    ok = false;
  }
  if (ok) check.drawn_mm = *length;
  const bool tolerance_ok = read_tolerance(reading, "drawn_mm", check.tolerance_mm);
  reading.settings = check;
  return tolerance_ok && ok;
}

ExpectationResult check(const scenario::Expectation& expectation, const FinishedRun& run) {
  const auto& check = settings_of<DrawnLengthCheck>(expectation);
  if (run.machine() == nullptr) return {false, "drawn_mm: the scenario has no machine"};
  const double drawn = run.machine()->stats().pen_down_mm;
  return {std::fabs(drawn - check.drawn_mm) <= check.tolerance_mm, "pen-down length " + millimetres(check.drawn_mm) +
                                                                       " mm ± " + millimetres(check.tolerance_mm) +
                                                                       ": got " + millimetres(drawn)};
}

}  // namespace

const ExpectationKind& drawn_length_expectation() {
  static const ExpectationKind kind{"drawn_mm", {"tolerance_mm"}, read, check};
  return kind;
}

}  // namespace stepdance::sim
