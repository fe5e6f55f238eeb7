// Locale-independent, deterministic number formatting shared by the text writers.
#pragma once

#include <string>

#include "common/sim_time.hpp"

namespace stepdance::sim {

/// `value` with exactly `decimals` digits after the point ("%.*f" in the C locale); a result
/// that rounds to zero is written without a minus sign; NaN is "nan", infinities "inf"/"-inf".
std::string format_fixed(double value, int decimals);

/// Like format_fixed, then trailing zeros (and a trailing point) removed: 1.500 → "1.5", 2.000 → "2".
std::string format_trimmed(double value, int max_decimals);

/// A time given in ns written in `unit_ns` units with `decimals` digits, computed with integer
/// arithmetic and rounded half away from zero: format_time(1'234'567, 1000, 3) = "1234.567".
/// Precondition: unit_ns is a power of ten from 1 to 1e9 and decimals ≤ 9.
std::string format_time(SimTime time_ns, SimTime unit_ns, int decimals);

}  // namespace stepdance::sim
