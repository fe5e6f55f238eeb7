// The one way a number is written on the command line: plain decimal text, nothing around it.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace stepdance::sim::scenario {

/// Reads `text` as a decimal number: an optional sign, digits with an optional fraction (".5",
/// "2.", "2.50"), an optional exponent ("1e-3"). Nothing else is a number here: no blanks on
/// either side, no hexadecimal ("0x10"), no digit separators. The words nan, inf and infinity
/// (any case, optionally signed) are read as what they name, so that a range check can refuse
/// them as not finite with the range in its message. A value beyond a double's range reads as
/// ±inf, one below its smallest as 0. Returns nothing when `text` is not such a number.
/// Context: any (pure).
std::optional<double> parse_decimal(std::string_view text);

/// Reads `text` as a decimal integer: an optional sign and digits, nothing around them.
/// Returns nothing when it is not one or does not fit in 64 bits. Context: any (pure).
std::optional<int64_t> parse_decimal_integer(std::string_view text);

}  // namespace stepdance::sim::scenario
