// Regular expressions from scenario files, checked before std::regex ever compiles them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace stepdance::sim::scenario {

/// A scenario's reply checks are short patterns. Longer ones, and counts beyond these, are
/// refused before std::regex sees them: libstdc++ reads a number in a pattern (a repeat count,
/// a back-reference) into a `long` without checking for overflow (undefined behaviour, found by
/// the scenario fuzz target), and it expands a repeat count into that many copies of its atom.
inline constexpr std::size_t kMaxPatternLength = 1000;
/// The largest count of `{n}`, `{n,}` or `{n,m}`.
inline constexpr std::uint32_t kMaxRepeatCount = 1000;
/// The largest back-reference number (`\1` … `\999`).
inline constexpr std::uint32_t kMaxBackReference = 999;

/// Empty if `pattern` is a usable ECMAScript regular expression, else what is wrong with it as
/// the rest of a sentence that starts with the key, e.g. "is not a valid regular expression
/// (ECMAScript syntax)". Context: host, scenario reading.
std::string regex_problem(std::string_view pattern);

}  // namespace stepdance::sim::scenario
