// One row per expectation kind: everything the simulator knows of a kind of [[expect]] check —
// the key that names it, its other keys, how it is read, and how it is checked and reported.
#pragma once

#include <any>
#include <string>
#include <string_view>
#include <vector>

#include "kinds/finished_run.hpp"
#include "scenario/parse_context.hpp"
#include "scenario/scenario.hpp"

namespace stepdance::sim {

/// The outcome of one [[expect]] entry.
struct ExpectationResult {
  bool met = false;
  /// `file:line: what was expected, and what happened` (also when met, for a report).
  std::string message;
  /// False when the run was stopped before its end and nothing was compared (never met then).
  bool checked = true;
};

/// What a kind's reader works on: the [[expect]] table (its check key is the only one there, and
/// no other kind's keys are), the scenario read so far, and the settings it fills.
struct ExpectationReading {
  scenario::TableReader& reader;
  scenario::ParseContext& context;
  /// The kind's settings (its own struct, e.g. MotorStepsCheck in kinds/expectations/motor.cpp).
  std::any settings;
};

/// An expectation kind. Register it with one line in kinds/builtin_expectation_kinds.cpp (or, in a
/// test, with a ScopedKind<ExpectationRegistry>: kinds/expectation_kinds.hpp); docs/architecture.md,
/// "Where things go", has the map.
struct ExpectationKind {
  /// The key that names the check, e.g. "motor" (`motor = "board:A"`).
  std::string_view name;
  /// Its other keys, e.g. {"steps"}. A key that goes with several kinds (tolerance_mm) is listed
  /// by each; any other kind's key in its table is reported as "only goes with".
  std::vector<std::string_view> keys;
  /// Reads the check key and the kind's keys into reading.settings; false (each error reported
  /// through the reader) if the check cannot be kept.
  bool (*read)(ExpectationReading& reading);
  /// Compares the finished run with the expectation read by `read`: met or not, and the report
  /// line (what was expected and what happened, without the file:line prefix).
  ExpectationResult (*check)(const scenario::Expectation& expectation, const FinishedRun& run);

  bool has_key(std::string_view key) const;
};

}  // namespace stepdance::sim
