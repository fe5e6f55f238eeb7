// A scenario error with its place in the file, printed as `file:line: message`.
#pragma once

#include <string>

namespace stepdance::sim::scenario {

/// One problem found in a scenario file.
struct Diagnostic {
  /// The scenario file as the user named it (for a folder: `<folder>/scenario.toml`).
  std::string file;
  /// 1-based line of the offending key, value or table; 0 when the problem is the whole file.
  int line = 0;
  std::string message;

  /// `file:line: message`, or `file: message` when line is 0.
  std::string to_string() const;
};

}  // namespace stepdance::sim::scenario
