// Reading a scenario file: TOML text → validated Scenario, or `file:line: message` errors.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "scenario/diagnostic.hpp"
#include "scenario/scenario.hpp"

namespace stepdance::sim::scenario {

/// A scenario, or every error found in it (sorted by line). Never throws.
struct LoadResult {
  /// Valid only when ok().
  Scenario scenario;
  std::vector<Diagnostic> errors;

  bool ok() const { return errors.empty(); }
  /// Every error as `file:line: message`, one per line.
  std::string error_text() const;
};

/// Loads a scenario file, or `<folder>/scenario.toml` when `path` is a folder.
LoadResult load_scenario(const std::string& path);

/// Parses scenario text as if it had been read from `file`: relative paths in it are resolved
/// against the folder of `file`, and errors name `file`.
LoadResult parse_scenario(std::string_view text, const std::string& file);

}  // namespace stepdance::sim::scenario
