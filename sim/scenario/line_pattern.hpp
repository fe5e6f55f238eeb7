// Reply patterns of scenario files ([[host.step]] wait/ack, [[expect]] reply checks): RE2, so a
// match takes time linear in the line whatever the pattern.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

namespace stepdance::sim::scenario {

/// The longest pattern, in bytes (a reply check is a short pattern).
inline constexpr std::size_t kMaxPatternLength = 1000;
/// The memory a pattern may compile into (RE2's max_mem, of which about two thirds go to the
/// program and the rest to the matcher's cache). RE2 refuses larger patterns when it compiles
/// them: a thousand repeats of forty short alternatives fit, of a hundred do not. RE2 itself
/// refuses repeat counts over 1,000, nested ones included (`(a{100}){100}`).
inline constexpr std::size_t kMaxPatternProgramBytes = 256 * 1024;

/// Empty if `pattern` is a usable pattern (RE2 syntax, bytes as Latin-1 so every byte of a line
/// is one character; at most kMaxPatternLength bytes; compiling within kMaxPatternProgramBytes),
/// else what is wrong with it as the rest of a sentence that starts with the key, e.g. "is not
/// a valid regular expression (RE2 syntax): missing ): (". Context: host, scenario reading.
std::string pattern_problem(std::string_view pattern);

/// A compiled pattern. Matching runs in time linear in the line (RE2 never backtracks), so a
/// pattern such as `^(a+)+$` cannot stall a run. Copies share the compiled program.
/// Context: host, one thread at a time.
class LinePattern {
 public:
  /// Compiles `pattern`. Precondition: pattern_problem(pattern) is empty (the scenario reader
  /// checked it); otherwise the pattern matches nothing.
  explicit LinePattern(std::string_view pattern);
  LinePattern();  ///< matches nothing

  /// Whether the pattern matches somewhere in `line` (anchor with ^…$ for the whole line).
  bool found_in(std::string_view line) const;

 private:
  struct Compiled;  ///< the engine's compiled program (RE2; the WebAssembly build's own, see its .cpp)
  std::shared_ptr<const Compiled> regex_;
};

}  // namespace stepdance::sim::scenario
