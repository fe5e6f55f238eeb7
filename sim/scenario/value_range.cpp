// Ranges of scenario and command-line numbers: checks and readable messages.
#include "scenario/value_range.hpp"

#include <cmath>
#include <sstream>

#include "scenario/decimal_text.hpp"

namespace stepdance::sim::scenario {

namespace {

/// Below this magnitude a whole number is printed in full, with separators.
constexpr double kSpelledOutLimit = 1e15;

std::string with_separators(uint64_t magnitude, bool negative) {
  std::string digits = std::to_string(magnitude);
  std::string out;
  for (size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return negative ? "-" + out : out;
}

std::string with_unit(std::string text, const char* unit) {
  if (unit != nullptr && unit[0] != '\0') text += std::string(" ") + unit;
  return text;
}

}  // namespace

bool in_range(double value, const NumberRange& range) {
  const bool above = range.low_open ? value > range.low : value >= range.low;
  return above && value <= range.high;  // nan fails both comparisons
}

bool in_range(int64_t value, const IntegerRange& range) { return value >= range.low && value <= range.high; }

std::string readable_number(double value) {
  if (std::isfinite(value) && std::fabs(value) < kSpelledOutLimit && value == std::floor(value)) {
    return with_separators(static_cast<uint64_t>(std::fabs(value)), value < 0);
  }
  std::ostringstream out;
  out.precision(6);
  out << value;
  return out.str();
}

std::string readable_integer(int64_t value) {
  const uint64_t magnitude = value < 0 ? 0 - static_cast<uint64_t>(value) : static_cast<uint64_t>(value);
  return with_separators(magnitude, value < 0);  // at most 19 digits: exact and still readable
}

std::string describe(const NumberRange& range) {
  return with_unit(
      std::string(range.low_open ? "(" : "[") + readable_number(range.low) + ", " + readable_number(range.high) + "]",
      range.unit);
}

std::string describe(const IntegerRange& range) {
  return with_unit("[" + readable_integer(range.low) + ", " + readable_integer(range.high) + "]", range.unit);
}

std::string out_of_range(std::string_view name, const NumberRange& range, double got) {
  return "'" + std::string(name) + "' must be in " + describe(range) + ", got " + readable_number(got);
}

std::string out_of_range(std::string_view name, const IntegerRange& range, int64_t got) {
  return "'" + std::string(name) + "' must be in " + describe(range) + ", got " + readable_integer(got);
}

std::optional<double> parse_number_option(std::string_view option, const std::string& text, const NumberRange& range,
                                          std::string& error) {
  const std::optional<double> value = parse_decimal(text);
  if (!value) {
    error = std::string(option) + ": '" + text + "' is not a decimal number (allowed: " + describe(range) + ")";
    return std::nullopt;
  }
  if (!in_range(*value, range)) {
    error = std::string(option) + ": must be in " + describe(range) + ", got " + text;
    return std::nullopt;
  }
  return value;
}

std::optional<int64_t> parse_integer_option(std::string_view option, const std::string& text, const IntegerRange& range,
                                            std::string& error) {
  const std::optional<int64_t> value = parse_decimal_integer(text);
  if (!value) {
    error = std::string(option) + ": '" + text + "' is not a whole decimal number (allowed: " + describe(range) + ")";
    return std::nullopt;
  }
  if (!in_range(*value, range)) {
    error = std::string(option) + ": must be in " + describe(range) + ", got " + text;
    return std::nullopt;
  }
  return value;
}

}  // namespace stepdance::sim::scenario
