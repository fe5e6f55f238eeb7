// pattern_problem and LinePattern in the WebAssembly build, which has no RE2: std::regex
// (ECMAScript grammar) on the line's bytes. The examples' patterns mean the same in both
// grammars; unlike RE2, this engine backtracks, so a pathological pattern is slow (in the page,
// only the user's own tab waits). docs/web.md lists the difference.
#include "scenario/line_pattern.hpp"

#include <regex>

namespace stepdance::sim::scenario {

struct LinePattern::Compiled {
  explicit Compiled(std::string_view pattern) : regex(pattern.begin(), pattern.end(), std::regex::ECMAScript) {}
  std::regex regex;
};

std::string pattern_problem(std::string_view pattern) {
  if (pattern.size() > kMaxPatternLength) {
    return "is longer than " + std::to_string(kMaxPatternLength) + " characters (a reply check is a short pattern)";
  }
  try {
    const std::regex regex(pattern.begin(), pattern.end(), std::regex::ECMAScript);
  } catch (const std::regex_error& error) {
    return std::string("is not a valid regular expression (ECMAScript syntax in the WebAssembly build): ") +
           error.what();
  }
  return {};
}

LinePattern::LinePattern() = default;

LinePattern::LinePattern(std::string_view pattern) {
  try {
    regex_ = std::make_shared<const Compiled>(pattern);
  } catch (const std::regex_error&) {
    regex_.reset();  // matches nothing, as the header says of an unchecked bad pattern
  }
}

bool LinePattern::found_in(std::string_view line) const {
  if (!regex_) return false;
  return std::regex_search(line.begin(), line.end(), regex_->regex);
}

}  // namespace stepdance::sim::scenario
