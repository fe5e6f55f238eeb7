// Scenario loading: file or folder → TOML → section readers → sorted timeline, or errors.
#include "scenario/load_scenario.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "scenario/parse_context.hpp"

namespace stepdance::sim::scenario {

namespace {

void read_top_level(TableReader& top, ParseContext& context) {
  if (const auto duration = top.number("duration_s", ranges::kDurationS, Need::kRequired)) {
    context.scenario.duration = from_seconds(*duration);
    context.duration_valid = true;
  }
  if (const auto seed = top.integer("seed", ranges::kSeed)) context.scenario.seed = static_cast<uint64_t>(*seed);
}

/// For a folder without scenario.toml: the sibling folders' scenarios whose sketch lies in it
/// (e.g. examples/ChainedKnobsBasic runs in examples/ChainedPlotterDriver/scenario.toml).
std::vector<std::string> scenarios_using(const std::filesystem::path& folder) {
  std::vector<std::string> users;
  std::error_code error;
  std::filesystem::path normal = folder.lexically_normal();
  if (!normal.has_filename()) normal = normal.parent_path();  // "examples/Knobs/" → "examples/Knobs"
  const std::string name = std::filesystem::absolute(normal, error).lexically_normal().filename().string();
  const std::filesystem::path parent = normal.parent_path();
  if (name.empty() || name == "." || name == "..") return users;
  for (const auto& sibling : std::filesystem::directory_iterator(parent.empty() ? "." : parent, error)) {
    const std::filesystem::path candidate = sibling.path() / "scenario.toml";
    if (!std::filesystem::is_regular_file(candidate, error)) continue;
    std::ifstream in(candidate);
    std::string line;
    while (std::getline(in, line)) {
      if (line.find("sketch") != std::string::npos && line.find("../" + name + "/") != std::string::npos) {
        users.push_back(candidate.string());
        break;
      }
    }
  }
  std::sort(users.begin(), users.end());
  return users;
}

std::string missing_scenario_message(const std::string& path, bool folder) {
  if (!folder) return "cannot read the scenario file (missing or not a file)";
  std::string message = "this folder has no scenario.toml";
  const std::vector<std::string> users = scenarios_using(path);
  for (size_t i = 0; i < users.size(); ++i) {
    message += (i == 0 ? "; its sketch runs in " : ", ") + users[i];
  }
  if (!users.empty()) {
    message += " (stepdance sim " + std::filesystem::path(users.front()).parent_path().string() + ")";
  }
  return message;
}

/// The 1-based line and "U+0001"-style code of the first control character other than tab, LF
/// and CR; line 0 when there is none.
std::pair<int, std::string> first_control_character(std::string_view text) {
  int line = 1;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte == '\n') ++line;
    if ((byte < 0x20 && byte != '\t' && byte != '\n' && byte != '\r') || byte == 0x7F) {
      static const char kHex[] = "0123456789ABCDEF";
      return {line, std::string("U+00") + kHex[byte >> 4] + kHex[byte & 15]};
    }
  }
  return {0, ""};
}

/// True for a character that can follow a line's opening '[' in valid TOML: the start of a key
/// (a table header) or of a value (a line of a multi-line array).
bool can_follow_opening_bracket(char c) {
  const bool bare_key = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
  return bare_key || c == '"' || c == '\'' || c == '+' || c == '.' || c == '{' || c == '[' || c == ']' || c == '#' ||
         c == '\r' || c == '\n';
}

/// The 1-based line of the first line that opens with '[' (or "[[", spaces allowed after either)
/// followed by a character that starts neither a key nor a value; 0 when there is none.
int first_bad_bracket_line(std::string_view text) {
  int line = 1;
  for (size_t start = 0; start < text.size(); ++line) {
    const size_t end = std::min(text.find('\n', start), text.size());
    size_t i = text.find_first_not_of(" \t", start);
    if (i < end && text[i] == '[') {
      ++i;
      if (i < end && text[i] == '[') ++i;
      while (i < end && (text[i] == ' ' || text[i] == '\t')) ++i;
      if (i < end && !can_follow_opening_bracket(text[i])) return line;
    }
    start = end + 1;
  }
  return 0;
}

/// The 1-based line of the first non-ASCII byte outside comments and strings (where TOML allows
/// none); 0 when there is none. A small lexer: comments run to the line's end; basic strings
/// ("…", """…""") take backslash escapes, literal strings ('…', \'\'\'…\'\'\') do not.
int first_non_ascii_outside_strings(std::string_view text) {
  int line = 1;
  size_t i = 0;
  auto starts = [&text](size_t at, const char* what) { return text.compare(at, 3, what) == 0; };
  while (i < text.size()) {
    const char c = text[i];
    if (c == '\n') ++line;
    if (static_cast<unsigned char>(c) >= 0x80) return line;
    if (c == '#') {
      i = std::min(text.find('\n', i), text.size());
      continue;
    }
    if (c != '"' && c != '\'') {
      ++i;
      continue;
    }
    const bool multi = starts(i, c == '"' ? "\"\"\"" : "\'\'\'");
    const std::string_view close = multi ? (c == '"' ? "\"\"\"" : "\'\'\'") : (c == '"' ? "\"" : "'");
    i += close.size();
    bool escaped = false;
    while (i < text.size() && (escaped || text.compare(i, close.size(), close) != 0)) {
      if (text[i] == '\n') {
        ++line;
        if (!multi) break;  // an unterminated string: toml++ reports it
      }
      escaped = c == '"' && text[i] == '\\' && !escaped;
      ++i;
    }
    i += close.size();
  }
  return 0;
}

}  // namespace

std::string LoadResult::error_text() const {
  std::string text;
  for (const Diagnostic& error : errors) text += error.to_string() + "\n";
  return text;
}

LoadResult load_scenario(const std::string& path) {
  std::string file = path;
  std::error_code error;
  const bool folder = std::filesystem::is_directory(path, error);
  if (folder) file = (std::filesystem::path(path) / "scenario.toml").string();
  std::ifstream in;
  if (std::filesystem::is_regular_file(file, error)) in.open(file, std::ios::binary);
  if (!in.is_open()) {
    LoadResult result;
    result.errors.push_back(Diagnostic{folder ? path : file, 0, missing_scenario_message(path, folder)});
    return result;
  }
  std::ostringstream text;
  text << in.rdbuf();
  return parse_scenario(text.str(), file);
}

LoadResult parse_scenario(std::string_view text, const std::string& file) {
  LoadResult result;
  Reporter reporter(file);
  // TOML allows no control character but tab, LF and CR anywhere; toml++ 3.3 asserts on one in a
  // table header (found by fuzz/scenario_fuzz.cpp), so they are refused before it parses.
  if (const auto [line, code] = first_control_character(text); line > 0) {
    reporter.error(line, "control character " + code + " is not allowed in a scenario file");
    result.errors = reporter.sorted();
    return result;
  }
  // toml++ 3.3 also asserts (undefined behaviour in a release build) on a table header whose
  // name starts with a character no key can start with, e.g. "[^at]" (found by the same fuzzer).
  if (const int line = first_bad_bracket_line(text); line > 0) {
    reporter.error(line, "a table header must start with a name (letters, digits, '_', '-' or a quoted key)");
    result.errors = reporter.sorted();
    return result;
  }
  // toml++ 3.3 reaches an unreachable point (undefined behaviour) classifying some non-ASCII
  // characters outside strings, e.g. 'µ' in an inline table (found by the same fuzzer). TOML
  // allows them only in comments and strings, so anything else is refused first.
  if (const int line = first_non_ascii_outside_strings(text); line > 0) {
    reporter.error(line, "a non-ASCII character outside a string or comment is not allowed in a scenario file");
    result.errors = reporter.sorted();
    return result;
  }
  toml::table root;
  try {
    root = toml::parse(text, file);
  } catch (const toml::parse_error& error) {
    reporter.error(static_cast<int>(error.source().begin.line), std::string(error.description()));
    result.errors = reporter.sorted();
    return result;
  }

  Scenario& scenario = result.scenario;
  std::error_code error;
  std::filesystem::path absolute = std::filesystem::absolute(std::filesystem::path(file), error);
  if (error) absolute = std::filesystem::path(file);
  absolute = absolute.lexically_normal();
  scenario.file = absolute.string();
  scenario.directory = absolute.parent_path().string();
  ParseContext context{reporter, absolute.parent_path(), scenario, false, {}};

  TableReader top(root, "the scenario", reporter);
  read_top_level(top, context);
  read_boards(top, context);
  read_machine(top, context);
  read_devices(top, context);
  read_cables(top, context);
  read_timeline(top, context);
  read_output(top, context);
  read_hosts(top, context);
  read_expectations(top, context);
  top.finish();

  std::stable_sort(scenario.timeline.begin(), scenario.timeline.end(),
                   [](const Action& a, const Action& b) { return a.time < b.time; });
  result.errors = reporter.sorted();
  return result;
}

}  // namespace stepdance::sim::scenario
