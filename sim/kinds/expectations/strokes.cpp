// Expectation kind "strokes": strokes = N — how many pen-down strokes the machine drew.
#include "kinds/expectations/strokes.hpp"

#include "kinds/expectations/expectation_parts.hpp"
#include "models/machine.hpp"

namespace stepdance::sim {
namespace {

bool read(ExpectationReading& reading) {
  const auto strokes = reading.reader.integer("strokes");
  if (!strokes) return false;
  reading.settings = StrokesCheck{*strokes};
  if (reading.context.scenario.machine) return true;
  reading.reader.error("strokes", "'strokes' needs a [machine]");
  return false;
}

ExpectationResult check(const scenario::Expectation& expectation, const FinishedRun& run) {
  if (run.machine() == nullptr) return {false, "strokes: the scenario has no machine"};
  return compare("pen-down strokes", settings_of<StrokesCheck>(expectation).strokes,
                 static_cast<int64_t>(run.machine()->strokes().size()));
}

}  // namespace

const ExpectationKind& strokes_expectation() {
  static const ExpectationKind kind{"strokes", {}, read, check};
  return kind;
}

}  // namespace stepdance::sim
