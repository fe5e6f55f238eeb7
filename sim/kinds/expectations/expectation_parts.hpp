// What several expectation kinds share: tolerance_mm, the settings of a read check, and the
// pieces of their report lines.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "kinds/expectation_kind.hpp"

namespace stepdance::sim {

/// The settings `read` stored in the expectation (a T: the kind's own struct).
template <typename T>
const T& settings_of(const scenario::Expectation& expectation) {
  return *expectation.settings_as<T>();
}

/// tolerance_mm (>= 0, finite; left alone when absent) and the [machine] every pen check needs,
/// reported at `key` (the check's key). False on either error.
bool read_tolerance(ExpectationReading& reading, const char* key, double& tolerance_mm);

/// 'port' (required): "board:OUT_A" or "board:IN_A", a port of an existing board; reported.
std::optional<scenario::PortLineRef> read_port_line(ExpectationReading& reading);

/// A length for a report line: "12.500".
std::string millimetres(double value);

/// "what: expected N, got M", met when they are equal.
ExpectationResult compare(const std::string& what, int64_t expected, int64_t actual);

/// "board:OUT_A" / "board:IN_A".
std::string port_name(const scenario::PortLineRef& port);

}  // namespace stepdance::sim
