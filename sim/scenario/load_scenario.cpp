// Scenario loading: file or folder → TOML → section readers → sorted timeline, or errors.
#include "scenario/load_scenario.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scenario/parse_context.hpp"

namespace stepdance::sim::scenario {

namespace {

/// Longest run a scenario may ask for: SimTime holds ~292 years, a day is plenty.
constexpr double kMaxDurationS = 86400;

void read_top_level(TableReader& top, ParseContext& context) {
  if (const auto duration = top.number("duration_s", Need::kRequired)) {
    if (*duration > 0 && *duration <= kMaxDurationS) {
      context.scenario.duration = from_seconds(*duration);
      context.duration_valid = true;
    } else {
      top.error("duration_s", "'duration_s' must be > 0 and at most 86400, got " + format_number(*duration));
    }
  }
  if (const auto seed = top.integer("seed")) {
    if (*seed >= 0) {
      context.scenario.seed = static_cast<uint64_t>(*seed);
    } else {
      top.error("seed", "'seed' must be >= 0, got " + std::to_string(*seed));
    }
  }
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
  if (std::filesystem::is_directory(path, error)) {
    file = (std::filesystem::path(path) / "scenario.toml").string();
  }
  std::ifstream in;
  if (std::filesystem::is_regular_file(file, error)) in.open(file, std::ios::binary);
  if (!in.is_open()) {
    LoadResult result;
    result.errors.push_back(Diagnostic{file, 0, "cannot read the scenario file (missing or not a file)"});
    return result;
  }
  std::ostringstream text;
  text << in.rdbuf();
  return parse_scenario(text.str(), file);
}

LoadResult parse_scenario(std::string_view text, const std::string& file) {
  LoadResult result;
  Reporter reporter(file);
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
