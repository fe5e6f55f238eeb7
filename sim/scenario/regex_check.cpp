// regex_problem: limits on length, repeat counts and back-references, then std::regex's own check.
#include "scenario/regex_check.hpp"

#include <regex>

namespace stepdance::sim::scenario {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

/// The number written at `at` (digits only), saturated just above `limit`; `at` moves past it.
std::uint32_t read_number(std::string_view text, std::size_t& at, std::uint32_t limit) {
  std::uint32_t value = 0;
  for (; at < text.size() && is_digit(text[at]); ++at) {
    if (value <= limit) value = value * 10 + static_cast<std::uint32_t>(text[at] - '0');
  }
  return value;
}

/// After '{' at `at`: the counts of a repeat `{n}`, `{n,}` or `{n,m}` (other text after '{' is
/// a literal brace, which std::regex then judges). True if a count is beyond the limit.
bool repeat_too_large(std::string_view text, std::size_t at) {
  ++at;
  if (at >= text.size() || !is_digit(text[at])) return false;
  if (read_number(text, at, kMaxRepeatCount) > kMaxRepeatCount) return true;
  if (at < text.size() && text[at] == ',') {
    ++at;
    if (read_number(text, at, kMaxRepeatCount) > kMaxRepeatCount) return true;
  }
  return false;
}

std::string with_thousands(std::uint32_t value) {
  std::string digits = std::to_string(value);
  for (std::size_t at = digits.size(); at > 3; at -= 3) digits.insert(at - 3, ",");
  return digits;
}

/// The first number in `pattern` beyond its limit, as a message; empty if none.
std::string number_problem(std::string_view pattern) {
  bool in_class = false;  // inside [...], where '{' is a literal
  for (std::size_t at = 0; at < pattern.size();) {
    const char c = pattern[at];
    if (c == '\\') {
      std::size_t digits = at + 1;
      if (digits < pattern.size() && is_digit(pattern[digits])) {
        if (read_number(pattern, digits, kMaxBackReference) > kMaxBackReference) {
          return "refers to a group beyond \\" + std::to_string(kMaxBackReference);
        }
        at = digits;
      } else {
        at += 2;  // an escaped character is never special
      }
      continue;
    }
    if (in_class) {
      in_class = c != ']';
    } else if (c == '[') {
      in_class = true;
    } else if (c == '{' && repeat_too_large(pattern, at)) {
      return "repeats more than " + with_thousands(kMaxRepeatCount) + " times";
    }
    ++at;
  }
  return {};
}

}  // namespace

std::string regex_problem(std::string_view pattern) {
  if (pattern.size() > kMaxPatternLength) {
    return "is longer than " + with_thousands(kMaxPatternLength) + " characters (a reply check is a short pattern)";
  }
  if (std::string problem = number_problem(pattern); !problem.empty()) return problem;
  try {
    std::regex check(pattern.begin(), pattern.end(), std::regex::ECMAScript);
  } catch (const std::regex_error&) {
    return "is not a valid regular expression (ECMAScript syntax)";
  }
  return {};
}

}  // namespace stepdance::sim::scenario
