// OutputFiles: which files a run writes, checked against each other and against the run's inputs,
// their folders made and checked writable before the run, and the lines a VCD records.
#include "assembly/output_files.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <set>

#include "assembly/vcd_size.hpp"
#include "board/loader/sketch_sources.hpp"
#include "kinds/device_kind.hpp"
#include "kinds/machine_kind.hpp"
#include "output/png_page.hpp"
#include "scenario/names.hpp"

namespace stepdance::sim {
namespace {

/// Creates `folder` (and its parents) and writes and removes a probe file in it; "" on success,
/// else why not. The probe is a new file (O_EXCL): a file of the same name is never touched.
std::string make_writable_folder(const std::filesystem::path& folder) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) return "cannot create the output folder " + folder.string() + ": " + error.message();
  const std::filesystem::path probe = folder / (".stepdance-write-test-" + std::to_string(::getpid()));
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) return "cannot write in the output folder " + folder.string();
  const bool written = ::write(fd, "ok", 2) == 2;
  ::close(fd);
  std::filesystem::remove(probe, error);
  return written ? "" : "cannot write in the output folder " + folder.string();
}

std::string at_line(const scenario::Scenario& scenario, int line) { return scenario.file + ":" + std::to_string(line); }

/// The files the scenario names as inputs: itself, every file of each board's sketch, the
/// files its timeline and host clients send.
std::vector<RunInput> scenario_inputs(const scenario::Scenario& scenario) {
  std::vector<RunInput> inputs{{scenario.file, "the scenario"}};
  for (const scenario::BoardConfig& board : scenario.boards) {
    SketchSources sources;
    std::string ignored;
    if (!find_sketch_sources(board.sketch, sources, ignored)) continue;
    const std::string what = "a file of the sketch of board '" + board.name + "'";
    for (const auto* group : {&sources.inos, &sources.cpp_files, &sources.c_files, &sources.headers}) {
      for (const std::string& file : *group) inputs.push_back({file, what});
    }
  }
  for (const scenario::Action& action : scenario.timeline) {
    if (!action.serial_file.empty())
      inputs.push_back({action.serial_file, "the serial file of line " + std::to_string(action.line)});
  }
  for (const scenario::HostClientConfig& host : scenario.hosts) {
    for (const scenario::HostStep& step : host.steps) {
      if (!step.file.empty()) inputs.push_back({step.file, "the stream_file of line " + std::to_string(step.line)});
    }
  }
  return inputs;
}

/// A plotter's page is its travel area: its PNG's size is known before the run. "" if it fits
/// (or the page is the drawing's bounding box, known only at the end), else the error.
std::string plotter_png_problem(const scenario::Scenario& scenario, const std::string& png) {
  if (png.empty() || !scenario.machine) return {};
  const std::optional<TravelArea> area =
      scenario.machine->kind->page ? scenario.machine->kind->page(*scenario.machine) : std::nullopt;
  if (!area) return {};
  DrawingStyle page;
  page.travel_width_mm = area->x_max_mm - area->x_min_mm;
  page.travel_height_mm = area->y_max_mm - area->y_min_mm;
  const std::string problem = png_size_problem(page, scenario.output.png_px_per_mm);
  if (problem.empty()) return {};
  char resolution[48];
  std::snprintf(resolution, sizeof resolution, "%g", scenario.output.png_px_per_mm);
  return at_line(scenario, scenario.machine->line) + ": at png_px_per_mm = " + resolution +
         ", the plotter's page (travel_mm and a " + std::to_string(static_cast<int>(page.margin_mm)) +
         " mm margin) is too large for a PNG: " + problem + " (lower png_px_per_mm or travel_mm, or set png = \"\")";
}

}  // namespace

OutputFiles::OutputFiles(const scenario::Scenario& scenario, const SimulationOptions& options)
    : scenario_(scenario), options_(options), directory_(options.output_directory.value_or(scenario.output.directory)) {
  vcd_path_ = options.vcd_file.value_or(path_of(scenario.output.vcd));
  if (!options.write_vcd) vcd_path_.clear();
  csv_path_ = options.csv_file.value_or(path_of(scenario.output.csv));
  html_path_ = options.html_file.value_or(path_of(scenario.output.html));
}

std::string OutputFiles::path_of(const std::string& configured) const {
  if (configured.empty() || !options_.output_directory) return configured;
  return (std::filesystem::path(*options_.output_directory) / std::filesystem::path(configured).filename()).string();
}

std::vector<PlannedOutput> OutputFiles::planned() const {
  std::vector<PlannedOutput> files;
  const auto add = [&files](const std::string& path, OutputOrigin origin, bool folder = false) {
    if (!path.empty()) files.push_back({path, std::move(origin), folder});
  };
  const auto key = [this](const char* name) {
    const auto found = scenario_.output.lines.find(name);
    if (found == scenario_.output.lines.end()) {
      return OutputOrigin{scenario_.file, "'" + std::string(name) + "' (its default name)", true};
    }
    return OutputOrigin{at_line(scenario_, found->second), "'" + std::string(name) + "'"};
  };
  // The boards' SD card folders first: a file asked for inside one is then the one reported.
  for (const scenario::BoardConfig& board : scenario_.boards) {
    add((std::filesystem::path(directory_) / (board.name + ".sd")).string(),
        {at_line(scenario_, board.line), "the SD card folder of board '" + board.name + "'"}, true);
  }
  add(vcd_path_, options_.vcd_file ? OutputOrigin{"--vcd", "--vcd"} : key("vcd"));
  add(csv_path_, options_.csv_file ? OutputOrigin{"--csv", "--csv"} : key("csv"));
  add(html_path_, options_.html_file ? OutputOrigin{"--html", "--html"} : key("html"));
  if (scenario_.machine) {
    add(path_of(scenario_.output.svg), key("svg"));
    if (options_.pictures) add(path_of(scenario_.output.png), key("png"));
  }
  add(path_of(scenario_.output.summary), key("summary"));
  for (const scenario::HostClientConfig& host : scenario_.hosts) {
    add(path_of(host.transcript), {at_line(scenario_, host.transcript_line), "'transcript'"});
  }
  for (const scenario::DeviceConfig& device : scenario_.devices) {
    if (device.kind->output_names == nullptr || !options_.pictures) continue;
    for (const std::string& name : device.kind->output_names(device)) {
      add(path_of((std::filesystem::path(scenario_.output.directory) / name).string()),
          {at_line(scenario_, device.line), "device '" + device.name + "''s picture " + name});
    }
  }
  for (PlannedOutput& file : files) file.path = std::filesystem::absolute(file.path).lexically_normal().string();
  return files;
}

bool OutputFiles::prepare(SimTime duration_ns, SimulationError& error) const {
  if (!vcd_path_.empty()) {
    std::string problem = vcd_size_problem(vcd_path_, vcd_ports().size(), duration_ns, options_.vcd_max_bytes);
    if (!problem.empty()) {
      error = {SimulationError::kBadInput, std::move(problem)};
      return false;
    }
  }
  const std::string png = options_.pictures ? path_of(scenario_.output.png) : std::string();
  if (const std::string problem = plotter_png_problem(scenario_, png); !problem.empty()) {
    error = {SimulationError::kBadInput, problem};
    return false;
  }
  const std::vector<PlannedOutput> files = planned();
  if (std::string conflicts = output_conflicts_text(files, scenario_inputs(scenario_)); !conflicts.empty()) {
    error = {SimulationError::kBadInput, std::move(conflicts)};
    return false;
  }
  std::set<std::filesystem::path> folders;
  for (const PlannedOutput& file : files) {
    if (file.folder) continue;  // a board's SD card folder is made when the board first uses it
    const std::filesystem::path path(file.path);
    std::error_code status;
    if (std::filesystem::is_directory(path, status)) {
      error = {SimulationError::kBadInput, "cannot write " + path.string() + ": it is a folder"};
      return false;
    }
    folders.insert(path.parent_path());
  }
  for (const std::filesystem::path& folder : folders) {
    const std::string problem = make_writable_folder(folder);
    if (!problem.empty()) {
      error = {SimulationError::kBadInput, problem};
      return false;
    }
  }
  return true;
}

std::vector<scenario::PortLineRef> OutputFiles::vcd_ports() const {
  if (!scenario_.output.vcd_ports.empty() || !options_.vcd_file) return scenario_.output.vcd_ports;
  std::vector<scenario::PortLineRef> ports;
  for (const scenario::BoardConfig& board : scenario_.boards) {
    for (char port = 'A'; port <= 'D'; ++port) {
      if (scenario::module_has_output_port(*board.module, port)) ports.push_back({board.name, true, port});
    }
  }
  for (const scenario::CableConfig& cable : scenario_.cables) ports.push_back({cable.to.board, false, cable.to.port});
  return ports;
}

}  // namespace stepdance::sim
