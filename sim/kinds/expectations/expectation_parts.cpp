// What several expectation kinds share: tolerance_mm and the pieces of their report lines.
#include "kinds/expectations/expectation_parts.hpp"

#include <cmath>
#include <cstdio>

namespace stepdance::sim {

bool read_tolerance(ExpectationReading& reading, const char* key, double& tolerance_mm) {
  scenario::TableReader& reader = reading.reader;
  bool ok = true;
  if (const auto tolerance = reader.number("tolerance_mm")) {
    if (*tolerance >= 0 && std::isfinite(*tolerance)) {
      tolerance_mm = *tolerance;
    } else {
      reader.error("tolerance_mm",
                   "'tolerance_mm' must be a finite number >= 0, got " + scenario::format_number(*tolerance));
      ok = false;
    }
  }
  if (!reading.context.scenario.machine) {
    reader.error(key, std::string("'") + key + "' needs a [machine]");
    ok = false;
  }
  return ok;
}

std::optional<scenario::PortLineRef> read_port_line(ExpectationReading& reading) {
  scenario::TableReader& reader = reading.reader;
  const auto text = reader.string("port", scenario::Need::kRequired);
  if (!text) return std::nullopt;
  return scenario::parse_port_line(*text, "port", reader.line_of("port"), reading.context);
}

std::string millimetres(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", value);
  return text;
}

ExpectationResult compare(const std::string& what, int64_t expected, int64_t actual) {
  return {expected == actual, what + ": expected " + std::to_string(expected) + ", got " + std::to_string(actual)};
}

std::string port_name(const scenario::PortLineRef& port) {
  return port.board + (port.output ? ":OUT_" : ":IN_") + port.port;
}

}  // namespace stepdance::sim
