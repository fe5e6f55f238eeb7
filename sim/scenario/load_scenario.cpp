// Scenario loading: file or folder → TOML → section readers → sorted timeline, or errors.
#include "scenario/load_scenario.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "scenario/parse_context.hpp"
#include "scenario/toml_guard.hpp"

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

/// The TOML tree of `text`, or nothing with the error reported.
std::optional<toml::table> parse_toml(std::string_view text, const std::string& file, Reporter& reporter) {
  // toml++ 3.3 asserts or reaches an unreachable point on some text TOML only calls an error;
  // that text is refused first (toml_guard.hpp lists it).
  if (const UnsafeToml unsafe = find_unsafe_toml(text); unsafe.line > 0) {
    reporter.error(unsafe.line, unsafe.message);
    return std::nullopt;
  }
  try {
    return toml::parse(text, file);
  } catch (const toml::parse_error& error) {
    reporter.error(static_cast<int>(error.source().begin.line), std::string(error.description()));
    return std::nullopt;
  }
}

/// `file` made absolute (as given when that fails), normalized.
std::filesystem::path absolute_path(const std::string& file) {
  std::error_code error;
  std::filesystem::path absolute = std::filesystem::absolute(std::filesystem::path(file), error);
  if (error) absolute = std::filesystem::path(file);
  return absolute.lexically_normal();
}

/// Every section, in the order the readers need (later ones refer to earlier ones).
void read_sections(TableReader& top, ParseContext& context) {
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
  std::optional<toml::table> root = parse_toml(text, file, reporter);
  if (!root) {
    result.errors = reporter.sorted();
    return result;
  }
  Scenario& scenario = result.scenario;
  const std::filesystem::path absolute = absolute_path(file);
  scenario.file = absolute.string();
  scenario.directory = absolute.parent_path().string();
  ParseContext context{reporter, absolute.parent_path(), scenario, false, {}};
  TableReader top(*root, "the scenario", reporter);
  read_sections(top, context);
  std::stable_sort(scenario.timeline.begin(), scenario.timeline.end(),
                   [](const Action& a, const Action& b) { return a.time < b.time; });
  result.errors = reporter.sorted();
  return result;
}

}  // namespace stepdance::sim::scenario
