// `stepdance sim`: scenario → Simulation → files, with a progress bar and a short report.
#include "sim_command.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>

#include "assembly/run_result.hpp"
#include "assembly/simulation.hpp"
#include "command_help.hpp"
#include "console_echo.hpp"
#include "containment.hpp"
#include "exit_codes.hpp"
#include "live_run.hpp"
#include "option_kinds.hpp"
#include "output/text_file.hpp"
#include "progress_bar.hpp"
#include "replay_page.hpp"
#include "scenario/load_scenario.hpp"
#include "scenario/value_range.hpp"
#include "simulator_hooks.hpp"
#include "view/replay_recorder.hpp"

namespace stepdance::cli {
namespace {

/// A live run ends when interrupted; this bounds it (a year of simulated time).
constexpr double kLiveDurationS = 365.0 * 86400.0;

namespace ranges = sim::scenario::ranges;

/// The numbers of the command line, checked by the scenario file's rules (value_range.hpp).
struct CheckedNumbers {
  std::optional<double> duration_s;
  std::optional<double> csv_interval_ms;
  std::optional<double> watchdog_s;
  std::optional<double> vcd_max_gb;
};

/// --watchdog-s: from a tenth of a second (tests) to a day; 10 s unless given.
constexpr sim::scenario::NumberRange kWatchdogS{0.1, 86400, false, "s"};
constexpr double kDefaultWatchdogS = 10;
/// --vcd-max-gb: the cap on the VCD's estimated size (sim/assembly/vcd_size.hpp), up to a petabyte.
constexpr sim::scenario::NumberRange kVcdMaxGb{0, 1e6, false, "GB"};

/// Checks an optional number option; false (message on stderr) when it is given and bad.
bool check_number(const char* option, const std::string& text, const sim::scenario::NumberRange& range,
                  std::optional<double>& out) {
  if (text.empty()) return true;
  out = read_number_option(option, text, range);
  return out.has_value();
}

bool check_numbers(const SimCommandOptions& options, CheckedNumbers& numbers) {
  return check_number("--duration", options.duration_s, ranges::kDurationS, numbers.duration_s) &&
         check_number("--csv-interval-ms", options.csv_interval_ms, ranges::kCsvIntervalMs, numbers.csv_interval_ms) &&
         check_number("--watchdog-s", options.watchdog_s, kWatchdogS, numbers.watchdog_s) &&
         check_number("--vcd-max-gb", options.vcd_max_gb, kVcdMaxGb, numbers.vcd_max_gb);
}

/// Options that only mean something in a live run: refused without --live (they used to be
/// ignored silently). False, with a message on stderr, when one is given.
bool check_live_only(const SimCommandOptions& options) {
  if (options.live) return true;
  if (!options.speed.empty()) std::cerr << "--speed: needs --live (it paces a live run)\n";
  if (!options.serial_links.empty()) std::cerr << "--serial-link: needs --live (it names a live run's terminal)\n";
  if (options.view) std::cerr << "--view: needs --live (it shows a live run)\n";
  if (!options.view_port.empty()) std::cerr << "--view-port: needs --live --view\n";
  return options.speed.empty() && options.serial_links.empty() && !options.view && options.view_port.empty();
}

/// Reads --view-port into `port` (0 when not given); false (message on stderr) when it is bad
/// or given without --view.
bool read_view_port(const SimCommandOptions& options, uint16_t& port) {
  port = 0;
  if (options.view_port.empty()) return true;
  if (!options.view) {
    std::cerr << "--view-port: needs --view\n";
    return false;
  }
  const auto value = read_integer_option("--view-port", options.view_port, ranges::kTcpPort);
  if (!value) return false;
  port = static_cast<uint16_t>(*value);
  return true;
}

/// A --serial-link path is replaced by a symlink and removed at the end: only a path that does
/// not exist, or a symlink (one an earlier run left), may be used. "" if `path` is fine.
std::string serial_link_problem(const std::string& path) {
  struct stat status {};
  if (lstat(path.c_str(), &status) != 0 || S_ISLNK(status.st_mode)) return {};
  return "'" + path + "' exists and is not a symlink; it would be deleted (name a new path)";
}

/// Reads --speed and --serial-link; false (with a message on stderr) when one is malformed.
bool parse_live_options(const SimCommandOptions& options, LiveOptions& live) {
  if (options.speed == "max") {
    live.speed = 0.0;
  } else if (!options.speed.empty()) {
    std::string error;
    const std::optional<double> speed =
        sim::scenario::parse_number_option("--speed", options.speed, ranges::kSpeed, error);
    if (!speed) {
      std::cerr << error << " (or 'max')\n";
      return false;
    }
    live.speed = *speed;
  }
  for (const std::string& link : options.serial_links) {
    const size_t equals = link.find('=');
    if (equals == std::string::npos || equals == 0 || equals + 1 == link.size()) {
      std::cerr << "--serial-link: '" << link << "' is not board=path\n";
      return false;
    }
    const std::string path = link.substr(equals + 1);
    if (const std::string problem = serial_link_problem(path); !problem.empty()) {
      std::cerr << "--serial-link: " << problem << "\n";
      return false;
    }
    live.serial_links[link.substr(0, equals)] = path;
  }
  return true;
}

std::string absolute_path(const std::string& path) {
  return std::filesystem::absolute(path).lexically_normal().string();
}

/// Reads --image board=path.elf into `images`; false (message on stderr) when one is malformed,
/// names a board twice, or names a file that does not exist.
bool parse_images(const SimCommandOptions& options, std::map<std::string, std::string>& images) {
  for (const std::string& entry : options.images) {
    const size_t equals = entry.find('=');
    if (equals == std::string::npos || equals == 0 || equals + 1 == entry.size()) {
      std::cerr << "--image: '" << entry << "' is not board=path.elf\n";
      return false;
    }
    const std::string board = entry.substr(0, equals);
    const std::string path = absolute_path(entry.substr(equals + 1));
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) {
      std::cerr << "--image: firmware image not found: " << path << "\n";
      return false;
    }
    if (!images.emplace(board, path).second) {
      std::cerr << "--image: board '" << board << "' is given twice\n";
      return false;
    }
  }
  return true;
}

sim::SimulationOptions simulation_options(const SimCommandOptions& options, const CheckedNumbers& numbers,
                                          ProgressBar& progress, ConsoleEcho& echo) {
  sim::SimulationOptions sim_options;
  plug_front_end(sim_options, options.cache_directory);
  if (numbers.duration_s) sim_options.duration = sim::from_seconds(*numbers.duration_s);
  if (!options.output_directory.empty()) sim_options.output_directory = absolute_path(options.output_directory);
  sim_options.write_vcd = !options.no_vcd;
  if (numbers.vcd_max_gb) sim_options.vcd_max_bytes = static_cast<uint64_t>(*numbers.vcd_max_gb * 1e9);
  if (!options.vcd_file.empty()) sim_options.vcd_file = absolute_path(options.vcd_file);
  if (!options.csv_file.empty()) sim_options.csv_file = absolute_path(options.csv_file);
  if (!options.html_file.empty()) sim_options.html_file = absolute_path(options.html_file);
  sim_options.csv_interval_ms = numbers.csv_interval_ms;
  sim_options.live = options.live;
  if (options.live) {
    // Runs until interrupted (or --duration); the terminals carry the console: nothing echoed.
    if (!numbers.duration_s) sim_options.duration = sim::from_seconds(kLiveDurationS);
    // Its length is the user's, not a year: the VCD's size is not estimated without --duration.
    if (!numbers.duration_s && !numbers.vcd_max_gb) sim_options.vcd_max_bytes = UINT64_MAX;
    return sim_options;
  }
  sim_options.progress = [&progress](sim::SimTime done, sim::SimTime total) { progress.update(done, total); };
  if (!options.quiet) {
    sim_options.console = [&echo](const std::string& board, const std::string& line) { echo.line(board, line); };
    sim_options.build_diagnostics = [&progress](const std::string& sketch, const std::string& text) {
      progress.clear();
      std::cerr << sketch << ": compiler warnings:\n" << text;
    };
  }
  return sim_options;
}

// A stopped sketch is reported whatever --quiet says: the run failed, or was cut short.
void print_stop(const sim::SimulationReport& report) {
  if (!report.sketch_stop) return;
  std::cerr << report.sketch_stop->message() << "\n";
  for (size_t i = 0; i < report.sketch_stop->backtrace.size(); ++i) {
    std::cerr << "  #" << i << " " << report.sketch_stop->backtrace[i] << "\n";
  }
}

// --result-json: the run's result document; throws std::runtime_error("path: …") when it cannot.
void write_result_json(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out.flush()) throw std::runtime_error(path + ": cannot write the run's result");
}

const char* result_label(const sim::ExpectationResult& result) {
  if (!result.checked) return "NOT RUN ";
  return result.met ? "ok      " : "FAILED  ";
}

// `live`: a live run's wall-clock time and computing time (zeros for a batch run, which computes
// all the time).
void print_report(const sim::SimulationReport& report, bool quiet, const LiveTiming& live) {
  for (const sim::ExpectationResult& result : report.expectations) {
    if (!result.met || !quiet) std::cout << result_label(result) << result.message << "\n";
  }
  if (quiet) return;
  const double simulated_s = sim::to_seconds(report.simulated_ns);
  char line[200];
  if (live.wall_s > 0) {
    std::snprintf(line, sizeof line,
                  "simulated %.3f s in %.3f s of wall time (live; %.3f s of it computing, %.1f %%)\n", simulated_s,
                  live.wall_s, live.computing_s, 100.0 * live.computing_s / live.wall_s);
  } else {
    std::snprintf(line, sizeof line, "simulated %.3f s in %.3f s of wall time (%.0fx real time)\n", simulated_s,
                  report.wall_s, report.wall_s > 0 ? simulated_s / report.wall_s : 0.0);
  }
  std::cout << line;
  for (const std::string& warning : report.warnings) std::cout << warning << "\n";
  if (live.paced_ms > 0) {
    std::snprintf(line, sizeof line,
                  "pacing: simulated time behind the wall clock by %.3f ms at most, %.3f ms on average "
                  "(%llu paced ms); %.3f ms given up (the run went slower than the clock)\n",
                  live.lag_max_ms, live.lag_mean_ms, static_cast<unsigned long long>(live.paced_ms), live.given_up_ms);
    std::cout << line;
  }
  for (const std::string& file : report.files) std::cout << "wrote " << file << "\n";
}

/// The replay page's recorder when the run writes one (--html or the scenario's html): sampled
/// by the simulation's pacer in a batch run, by the live run's ticks in a live one.
std::unique_ptr<sim::view::ReplayRecorder> make_replay(sim::Simulation& simulation, bool is_live, LiveOptions& live) {
  if (simulation.html_path().empty()) return nullptr;
  const sim::view::ReplayLimits limits;
  // A live run's end is not known: its instants are as close as they may be.
  const sim::SimTime interval = sim::view::replay_interval_ns(is_live ? 0 : simulation.duration(), limits);
  auto replay = std::make_unique<sim::view::ReplayRecorder>(simulation, interval, limits);
  if (!is_live) {
    replay->attach_pacer();
    return replay;
  }
  sim::view::ReplayRecorder* recorder = replay.get();
  live.on_tick = [recorder](sim::SimTime now) { recorder->sample(now); };
  live.on_console = [recorder](const std::string& board, const uint8_t* data, size_t length) {
    recorder->console(board, data, length);
  };
  return replay;
}

// A --serial-link naming no board is bad input (docs/simulator.md), said before anything runs.
bool serial_links_name_boards(const LiveOptions& live, const sim::scenario::Scenario& scenario) {
  for (const auto& [name, path] : live.serial_links) {
    const bool found = std::any_of(scenario.boards.begin(), scenario.boards.end(),
                                   [&](const auto& board) { return board.name == name; });
    if (!found) {
      std::cerr << "--serial-link: no board named '" << name << "'\n";
      return false;
    }
  }
  return true;
}

int exit_status(const sim::SimulationReport& report) {
  if (report.sketch_stop) {
    switch (report.sketch_stop->cause) {
      case sim::EscapeCause::kHung: return kExitSketchHung;
      case sim::EscapeCause::kCrashed:
      case sim::EscapeCause::kEnded: return kExitSketchFailed;
      default: break;
    }
  }
  if (report.interrupted_by != 0) return kExitSignalBase + report.interrupted_by;
  if (report.sketch_stop && report.sketch_stop->cause == sim::EscapeCause::kInterrupted &&
      !report.all_expectations_met()) {
    return kExitExpectationFailed;
  }
  return report.all_expectations_met() ? kExitOk : kExitExpectationFailed;
}

/// A [[host]] client cannot run with --live (there the host is the program on the terminal).
bool hosts_allowed(const SimCommandOptions& options, const sim::scenario::Scenario& scenario) {
  if (!options.live || scenario.hosts.empty()) return true;
  std::cerr << scenario.file << ":" << scenario.hosts.front().line
            << ": a [[host]] client cannot run with --live: there the host is the program on the terminal\n";
  return false;
}

/// The live run, until interrupted, with the live view when asked (it ends with the run).
LiveTiming run_live_with_view(sim::Simulation& simulation, const SimCommandOptions& options,
                              const sim::scenario::Scenario& scenario, LiveOptions& live, uint16_t view_port) {
  std::vector<std::string> boards;
  for (const auto& board : scenario.boards) boards.push_back(board.name);
  std::unique_ptr<LiveView> view;
  if (options.view) {
    if (!options.make_view) throw std::runtime_error("--view: this build has no live view");
    view = options.make_view(simulation, view_port);
    live.view = view.get();
  }
  return run_live(simulation, boards, live);
}

/// Runs (live or at once) to the end, then writes the replay page and the result JSON when asked.
/// Throws std::exception when the run or a file fails.
sim::SimulationReport run_to_end(sim::Simulation& simulation, const SimCommandOptions& options,
                                 const sim::scenario::Scenario& scenario, LiveOptions& live, uint16_t view_port,
                                 LiveTiming& live_timing) {
  std::unique_ptr<sim::view::ReplayRecorder> replay = make_replay(simulation, options.live, live);
  if (options.live) live_timing = run_live_with_view(simulation, options, scenario, live, view_port);
  sim::SimulationReport report = simulation.finish();
  if (replay) {
    sim::write_text_file(simulation.html_path(), replay_page_html(replay->recording()));
    report.files.push_back(simulation.html_path());
  }
  if (!options.result_json.empty()) write_result_json(options.result_json, sim::run_result_json(simulation, report));
  return report;
}

}  // namespace

CLI::App& add_sim_command(CLI::App& app, SimCommandOptions& options) {
  CLI::App& sim = add_command(
      app, "sim",
      "Run a simulation: the boards' sketches (compiled for the host, cached), devices, cables and machine "
      "described by a scenario file, then write the drawing, VCD, CSV and summary it asks for and check its "
      "[[expect]] entries.",
      {{kExitOk, "ok"},
       {kExitFailure, "failure"},
       {kExitBadInput, "bad scenario or sketch"},
       {kExitExpectationFailed, "an expectation failed"},
       {kExitSketchFailed, "a sketch crashed or ended the program"},
       {kExitSketchHung, "a sketch hung"},
       {kExitSignalBase + SIGINT, "interrupted by SIGINT/SIGTERM", kExitSignalBase + SIGTERM}});
  sim.add_option("scenario", options.scenario_path, "a scenario .toml file, or an example folder holding scenario.toml")
      ->required();
  add_output_folder_option(sim, options.output_directory, "");
  add_number_option(sim, "--duration", options.duration_s,
                    "simulated seconds to run instead of duration_s, in " + describe(ranges::kDurationS));
  add_path_option(sim, "--vcd", options.vcd_file,
                  "write a VCD here (every output port and cabled input port unless the scenario lists vcd_ports)");
  add_path_option(sim, "--csv", options.csv_file, "write the CSV of positions over time here");
  add_path_option(sim, "--html", options.html_file,
                  "write the replay page here: one self-contained HTML file replaying the run with a time slider "
                  "(drawing, pen, inputs, console, the output ports' wire)");
  add_number_option(sim, "--csv-interval-ms", options.csv_interval_ms,
                    "CSV sampling interval instead of csv_interval_ms, in " + describe(ranges::kCsvIntervalMs));
  sim.add_flag("--no-vcd", options.no_vcd, "do not write the VCD file");
  add_number_option(sim, "--vcd-max-gb", options.vcd_max_gb,
                    "refuse a run whose VCD could pass this many GB (default 1; the estimate: 1.425 MB per recorded "
                    "port and simulated second), in " +
                        describe(kVcdMaxGb));
  sim.add_flag("--quiet", options.quiet, "print only failures (no sketch output, progress or report)");
  sim.add_flag("--live", options.live,
               "run in real time until interrupted (Ctrl-C), each board's USB serial on a pseudo-terminal announced "
               "as `serial <board>: <path>`; outputs are written when the run ends");
  add_number_option(
      sim, "--speed", options.speed,
      "live only: simulated seconds per wall-clock second, in " + describe(ranges::kSpeed) + ", or 'max' (default 1)");
  sim.add_option("--image", options.images,
                 "run a board on its firmware image instead of its host-compiled sketch (board=path.elf: a Teensy 4.x "
                 "ELF as the Arduino IDE or scripts/build-teensy.sh links it, run on an emulated i.MX RT1062)");
  sim.add_option("--serial-link", options.serial_links,
                 "live only: also make a symlink to a board's terminal (board=path; path must not exist, or be a "
                 "symlink)");
  sim.add_flag("--view", options.view,
               "live only: also serve a page showing the machine, the drawing, each board's devices as controls "
               "and its console, on 127.0.0.1, announced as `view: http://127.0.0.1:PORT/?token=…`");
  add_number_option(sim, "--view-port", options.view_port,
                    "live view: the TCP port, in [0, 65,535] (default 0: any free port)");
  add_number_option(sim, "--watchdog-s", options.watchdog_s,
                    "stop a sketch that runs this many seconds of wall time without simulated time moving (default "
                    "10, in " +
                        describe(kWatchdogS) + ")");
  sim.add_option("--result-json", options.result_json,
                 "also write the run's result as JSON to this file: the summary without wall time and every "
                 "expectation's outcome (the WebAssembly build prints the same document)");
  add_cache_folder_option(sim, options.cache_directory, "");
  return sim;
}

int run_sim_command(const SimCommandOptions& options) {
  CheckedNumbers numbers;
  LiveOptions live;
  uint16_t view_port = 0;
  std::map<std::string, std::string> images;
  if (!check_numbers(options, numbers) || !check_live_only(options) || !parse_live_options(options, live) ||
      !read_view_port(options, view_port) || !parse_images(options, images)) {
    return kExitBadInput;
  }
  const sim::scenario::LoadResult loaded = sim::scenario::load_scenario(options.scenario_path);
  if (!loaded.ok()) {
    std::cerr << loaded.error_text();
    return kExitBadInput;
  }
  if (!serial_links_name_boards(live, loaded.scenario) || !hosts_allowed(options, loaded.scenario))
    return kExitBadInput;
  ProgressBar progress(!options.quiet && !options.live);
  ConsoleEcho echo([&progress] { progress.clear(); });
  sim::SimulationError error;
  sim::SimulationOptions sim_options = simulation_options(options, numbers, progress, echo);
  sim_options.images = std::move(images);
  auto simulation = sim::Simulation::create(loaded.scenario, sim_options, error);
  if (!simulation) {
    std::cerr << error.message << (error.message.empty() || error.message.back() != '\n' ? "\n" : "");
    return error.kind == sim::SimulationError::kBadInput ? kExitBadInput : kExitFailure;
  }
  sim::SimulationReport report;
  Containment containment(numbers.watchdog_s.value_or(kDefaultWatchdogS));
  LiveTiming live_timing;
  try {
    report = run_to_end(*simulation, options, loaded.scenario, live, view_port, live_timing);
  } catch (const std::exception& failure) {
    progress.clear();
    std::cerr << failure.what() << "\n";
    return kExitFailure;
  }
  echo.flush();
  progress.clear();
  std::cout.flush();
  print_stop(report);
  print_report(report, options.quiet, live_timing);
  return exit_status(report);
}

}  // namespace stepdance::cli
