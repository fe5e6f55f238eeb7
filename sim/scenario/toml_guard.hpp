// Text that toml++ 3.3 (Debian 12's) cannot be trusted with, found before it parses.
#pragma once

#include <cstddef>
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
///    ahead to tell its type and asserts on some it cannot type; no scenario value is a date);
///  - a key (of a key/value pair, an inline table or a table header) of more than kMaxKeyParts
///    dotted parts or kMaxKeyChars characters: toml++ recurses once per dotted part, and a key
///    of 40,000 parts overflowed the stack. No scenario key has more than three.
/// A string starts only where TOML lets one start (a key at a line's start, after '{', ',' or
/// '.', or in a table header; a value after '=', '[' or ','), so a quote toml++ reads as a
/// stray character is one here too.
/// The most dotted parts a key may have (`a.b.c` has three).
inline constexpr std::size_t kMaxKeyParts = 16;
/// The longest key, in characters, quotes and dots included.
inline constexpr std::size_t kMaxKeyChars = 256;

struct UnsafeToml {
  int line = 0;         ///< 1-based; 0 when the text is safe to parse
  std::string message;  ///< the error to report at that line
};

/// The first unsafe place in `text`, or line 0. Context: host, scenario reading.
UnsafeToml find_unsafe_toml(std::string_view text);

}  // namespace stepdance::sim::scenario
