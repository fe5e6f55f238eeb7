// pattern_problem and LinePattern: RE2 with Latin-1 bytes, quiet errors and a bounded program.
#include "scenario/line_pattern.hpp"

#include <re2/re2.h>

namespace stepdance::sim::scenario {
namespace {

RE2::Options pattern_options() {
  RE2::Options options;
  options.set_encoding(RE2::Options::EncodingLatin1);  // a line is bytes, as the board sent them
  options.set_log_errors(false);
  options.set_max_mem(static_cast<int64_t>(kMaxPatternProgramBytes));
  return options;
}

std::string with_thousands(std::size_t value) {
  std::string digits = std::to_string(value);
  for (std::size_t at = digits.size(); at > 3; at -= 3) digits.insert(at - 3, ",");
  return digits;
}

}  // namespace

struct LinePattern::Compiled {
  explicit Compiled(std::string_view pattern)
      : regex(re2::StringPiece(pattern.data(), pattern.size()), pattern_options()) {}
  RE2 regex;
};

std::string pattern_problem(std::string_view pattern) {
  if (pattern.size() > kMaxPatternLength) {
    return "is longer than " + with_thousands(kMaxPatternLength) + " characters (a reply check is a short pattern)";
  }
  const RE2 regex(re2::StringPiece(pattern.data(), pattern.size()), pattern_options());
  if (regex.ok()) return {};
  if (regex.error_code() == RE2::ErrorPatternTooLarge) {
    return "is too complex: it compiles to more than " + with_thousands(kMaxPatternProgramBytes / 1024) +
           " KiB (simplify it)";
  }
  return "is not a valid regular expression (RE2 syntax): " + regex.error();
}

LinePattern::LinePattern() = default;

LinePattern::LinePattern(std::string_view pattern) : regex_(std::make_shared<const Compiled>(pattern)) {}

bool LinePattern::found_in(std::string_view line) const {
  if (!regex_ || !regex_->regex.ok()) return false;
  return RE2::PartialMatch(re2::StringPiece(line.data(), line.size()), regex_->regex);
}

}  // namespace stepdance::sim::scenario
