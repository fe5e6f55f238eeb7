// parse_decimal, parse_decimal_integer: a strict grammar first, then the C library converts.
#include "scenario/decimal_text.hpp"

#include <cerrno>
#include <cstdlib>
#include <limits>
#include <string>

namespace stepdance::sim::scenario {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

/// Moves `at` past the digits there; the number of digits passed.
std::size_t skip_digits(std::string_view text, std::size_t& at) {
  const std::size_t start = at;
  while (at < text.size() && is_digit(text[at])) ++at;
  return at - start;
}

/// Moves `at` past one '+' or '-', if there is one.
void skip_sign(std::string_view text, std::size_t& at) {
  if (at < text.size() && (text[at] == '+' || text[at] == '-')) ++at;
}

char lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

bool equals_ignoring_case(std::string_view text, std::string_view word) {
  if (text.size() != word.size()) return false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (lower(text[i]) != word[i]) return false;
  }
  return true;
}

/// nan, inf or infinity after an optional sign.
std::optional<double> non_finite_word(std::string_view text) {
  std::size_t at = 0;
  skip_sign(text, at);
  const std::string_view word = text.substr(at);
  const bool negative = at > 0 && text[0] == '-';
  if (equals_ignoring_case(word, "nan")) return std::numeric_limits<double>::quiet_NaN();
  if (equals_ignoring_case(word, "inf") || equals_ignoring_case(word, "infinity")) {
    return negative ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
  }
  return std::nullopt;
}

/// Whether the whole of `text` is sign, mantissa and optional exponent.
bool is_decimal_syntax(std::string_view text) {
  std::size_t at = 0;
  skip_sign(text, at);
  std::size_t digits = skip_digits(text, at);
  if (at < text.size() && text[at] == '.') {
    ++at;
    digits += skip_digits(text, at);
  }
  if (digits == 0) return false;
  if (at < text.size() && (text[at] == 'e' || text[at] == 'E')) {
    ++at;
    skip_sign(text, at);
    if (skip_digits(text, at) == 0) return false;
  }
  return at == text.size();
}

}  // namespace

std::optional<double> parse_decimal(std::string_view text) {
  if (const auto word = non_finite_word(text)) return word;
  if (!is_decimal_syntax(text)) return std::nullopt;
  const std::string copy(text);  // strtod needs a terminator; the grammar above leaves it nothing to skip
  return std::strtod(copy.c_str(), nullptr);
}

std::optional<int64_t> parse_decimal_integer(std::string_view text) {
  std::size_t at = 0;
  skip_sign(text, at);
  if (skip_digits(text, at) == 0 || at != text.size()) return std::nullopt;
  const std::string copy(text);
  errno = 0;
  const long long value = std::strtoll(copy.c_str(), nullptr, 10);
  if (errno == ERANGE) return std::nullopt;
  return static_cast<int64_t>(value);
}

}  // namespace stepdance::sim::scenario
