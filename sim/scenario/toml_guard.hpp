// Text that toml++ 3.3 (Debian 12's) cannot be trusted with, found before it parses.
#pragma once

#include <string>
#include <string_view>

namespace stepdance::sim::scenario {

/// Where toml++ 3.3 would assert or reach an unreachable point (undefined behaviour in its
/// release build) on text that TOML only calls an error, as fuzz/scenario_fuzz.cpp found:
///  - a control character other than tab, LF and CR, or a CR without LF (TOML allows none of
///    them; toml++ asserts on one in a table header);
///  - a non-ASCII character outside strings and comments, or after a backslash in a string
///    (toml++'s whitespace test reaches an unreachable point for most of U+00A1–U+0499,
///    U+2F2E–U+3327 and U+FBA6–U+FEFE; TOML allows non-ASCII text only in strings and comments);
///  - a table header whose name does not start like a key (`[^a]`, `[[.x`);
///  - '}' right after '[' or ',' in an array;
///  - an unquoted value other than true, false or a TOML number (toml++ scans such a value
///    ahead to tell its type and asserts on some it cannot type; no scenario value is a date).
/// A string starts only where TOML lets one start (a key at a line's start, after '{', ',' or
/// '.', or in a table header; a value after '=', '[' or ','), so a quote toml++ reads as a
/// stray character is one here too.
struct UnsafeToml {
  int line = 0;         ///< 1-based; 0 when the text is safe to parse
  std::string message;  ///< the error to report at that line
};

/// The first unsafe place in `text`, or line 0. Context: host, scenario reading.
UnsafeToml find_unsafe_toml(std::string_view text);

}  // namespace stepdance::sim::scenario
