// `stepdance sim`: run a scenario (or an example folder's scenario.toml) and write its outputs.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace stepdance::sim {
class Simulation;
}

namespace stepdance::cli {

class LiveView;

/// Makes the live view's server on a port (0: any free one); throws std::runtime_error.
using LiveViewFactory = std::function<std::unique_ptr<LiveView>(sim::Simulation&, uint16_t port)>;

/// Options of `stepdance sim`.
struct SimCommandOptions {
  std::string scenario_path;
  std::string output_directory;  ///< empty: the scenario's [output] directory
  std::string duration_s;        ///< replaces duration_s ("" = the file's); checked like it
  std::string vcd_file;          ///< write a VCD here ("" = the scenario's)
  std::string csv_file;          ///< write a CSV here ("" = the scenario's)
  std::string html_file;         ///< write the replay page here ("" = the scenario's)
  std::string csv_interval_ms;   ///< replaces csv_interval_ms ("" = the file's); checked like it
  bool no_vcd = false;
  std::string vcd_max_gb;  ///< the cap on the VCD's estimated size, GB ("" = 1)
  bool quiet = false;
  std::string cache_directory;            ///< empty: the default sketch cache
  bool live = false;                      ///< pace to the wall clock, serial ports on terminals
  std::string speed;                      ///< live: simulated seconds per wall second, or "max" ("" = 1)
  std::vector<std::string> serial_links;  ///< live: `board=path` symlinks to the terminals
  std::vector<std::string> images;        ///< `board=path.elf`: the board runs this firmware image
  std::string watchdog_s = "10";          ///< wall seconds a sketch may run with simulated time stuck
  bool view = false;                      ///< live: serve the view page (web/view/)
  std::string view_port;                  ///< live view: the TCP port ("" = any free one)
  std::string result_json;                ///< write the run's result here (sim/assembly/run_result.hpp); "" = none
  /// Builds the view's server (main.cpp plugs in cli/view's, which keeps Boost out of this
  /// library); --view is refused without one.
  LiveViewFactory make_view;
};

/// Adds the `sim` subcommand to `app`, filling `options` when it is parsed.
CLI::App& add_sim_command(CLI::App& app, SimCommandOptions& options);

/// Loads the scenario, builds the sketches, runs and writes the outputs. Returns kExitOk,
/// kExitBadInput (scenario or sketch errors, printed as `file:line: message`), kExitFailure
/// (an output could not be written), kExitExpectationFailed, kExitSketchFailed, kExitSketchHung
/// or kExitSignalBase + the signal that interrupted a batch run.
int run_sim_command(const SimCommandOptions& options);

}  // namespace stepdance::cli
