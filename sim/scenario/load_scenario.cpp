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

/// What toml++ 3.3 cannot be trusted with (it asserts, or reaches an unreachable point, where
/// TOML only asks for an error), found by fuzz/scenario_fuzz.cpp.
struct UnsafeText {
  int line = 0;  ///< 1-based; 0 when the text is safe
  const char* message = "";
};

bool starts_a_key(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-' ||
         c == '"' || c == '\'';
}

/// A small lexer over the text: comments run to the line's end; basic strings ("…", """…""")
/// take backslash escapes, literal strings ('…', \'\'\'…\'\'\') do not; '[' and '{' inside values
/// nest. Outside strings and comments it finds the first non-ASCII byte (TOML allows none there)
/// and the first table header — a '[' opening a line outside any value — whose name does not
/// start like a key, and the first '}' right after '[' or ',' (whitespace and comments between).
UnsafeText find_unsafe_text(std::string_view text) {
  int line = 1, depth = 0;
  bool line_start = true;
  char previous = '\n';  // the last character outside whitespace, comments and strings
  size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (c == '\n') {
      ++line;
      line_start = true;
    }
    if (static_cast<unsigned char>(c) >= 0x80) return {line, "a non-ASCII character outside a string or comment is not allowed in a scenario file"};
    if (c == '#') {
      i = std::min(text.find('\n', i), text.size());
      continue;
    }
    if (c == '[' && depth == 0 && line_start) {  // a table header
      size_t j = i + 1;
      if (j < text.size() && text[j] == '[') ++j;
      while (j < text.size() && (text[j] == ' ' || text[j] == '\t')) ++j;
      if (j >= text.size() || (!starts_a_key(text[j]) && text[j] != ']')) {
        return {line, "a table header must start with a name (letters, digits, '_', '-' or a quoted key)"};
      }
      line_start = false;
      i = j;
      continue;
    }
    if (c != ' ' && c != '\t' && c != '\r' && c != '\n') {
      line_start = false;
      // toml++ 3.3 asserts (undefined behaviour without assertions) on "[}" or ",}" in an array.
      if (c == '}' && (previous == '[' || previous == ',')) return {line, "'}' cannot follow '[' or ','"};
      previous = c;
    }
    if (c == '[' || c == '{') ++depth;
    if ((c == ']' || c == '}') && depth > 0) --depth;
    if (c != '"' && c != '\'') {
      ++i;
      continue;
    }
    const bool multi = text.compare(i, 3, c == '"' ? "\"\"\"" : "\'\'\'") == 0;
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
  return {};
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
  // toml++ 3.3 asserts or reaches an unreachable point on some text TOML only calls an error
  // (a table header starting with '^', a 'µ' outside a string, '}' after '[' or ',' in an array),
  // so that text is refused first.
  if (const UnsafeText unsafe = find_unsafe_text(text); unsafe.line > 0) {
    reporter.error(unsafe.line, unsafe.message);
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
