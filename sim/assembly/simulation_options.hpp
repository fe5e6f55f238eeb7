// What a simulation is asked to do beyond its scenario, why it could not be built, and what a
// finished run produced: the words every assembly part (board_set.hpp, output_files.hpp, …) and
// the front ends share.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "board/host/board_firmware.hpp"
#include "board/host/board_source.hpp"
#include "board/host/sketch_stop.hpp"
#include "common/sim_time.hpp"
#include "kinds/expectation_kind.hpp"
#include "output/picture_writer.hpp"
#include "scenario/scenario.hpp"

namespace stepdance::sim {

/// How to run a scenario, beyond what the scenario file says.
struct SimulationOptions {
  /// Gives each board's library for its sketch: SketchBuilder compiles them (the command line,
  /// the tests); a build without a compiler hands precompiled ones. Null: no board can be built.
  std::shared_ptr<const BoardSource> boards;
  /// Loads the firmware images boards run instead of their sketches (sim/image's ImageSource).
  /// Null: a scenario or option that names an image is refused.
  std::shared_ptr<const FirmwareSource> firmware;
  /// Firmware images by board name (`stepdance sim --image BOARD=PATH.elf`), replacing the
  /// scenario's `image` keys. A name no board has is refused.
  std::map<std::string, std::string> images;
  /// Writes the drawing's and the devices' pictures (png_picture_writer.hpp, the PNG module).
  /// Null: no picture is planned or written, whatever the scenario names.
  std::shared_ptr<const PictureWriter> pictures;
  /// Replaces the scenario's duration.
  std::optional<SimTime> duration;
  /// Replaces the output directory; the files keep their names.
  std::optional<std::string> output_directory;
  /// False skips the VCD even if the scenario asks for one.
  bool write_vcd = true;
  /// A run whose VCD could pass this many bytes (vcd_size.hpp's estimate) is refused at create().
  uint64_t vcd_max_bytes = 1000ull * 1000 * 1000;
  /// A live run: Ctrl-C or SIGTERM end it normally (expectations are checked) instead of cutting
  /// it short.
  bool live = false;
  /// Write the VCD (or CSV) here, whatever the scenario says (exact paths, not moved by
  /// output_directory). A VCD asked for this way records every output port and every cabled
  /// input port when the scenario names no vcd_ports.
  std::optional<std::string> vcd_file;
  std::optional<std::string> csv_file;
  /// The replay page's path instead of the scenario's html (an exact path, like vcd_file). The
  /// simulation checks it with the other outputs before the run; the front end writes it.
  std::optional<std::string> html_file;
  /// Replaces the scenario's csv_interval_ms (checked by the caller against ranges::kCsvIntervalMs).
  std::optional<double> csv_interval_ms;
  /// Called now and then with (simulated time so far, total), for a progress bar.
  std::function<void(SimTime, SimTime)> progress;
  /// Called with every line a sketch prints on Serial: (board name, line).
  std::function<void(const std::string&, const std::string&)> console;
  /// Called with compiler warnings of a freshly built sketch: (sketch path, text).
  std::function<void(const std::string&, const std::string&)> build_diagnostics;
};

/// Why a simulation could not be built.
struct SimulationError {
  /// kBadInput: the scenario or a sketch is wrong (the message says where); kFailure: the
  /// machine failed (cannot write, cannot load).
  enum Kind { kBadInput, kFailure } kind = kBadInput;
  std::string message;
};

/// What a finished run produced.
struct SimulationReport {
  SimTime simulated_ns = 0;
  double wall_s = 0;
  /// The sketch the simulator had to stop (a crash, exit(), a hang, an interrupt inside its
  /// code), if any: the run ended there.
  std::optional<SketchStop> sketch_stop;
  /// SIGINT or SIGTERM when the run was cut short by one (0 if not, or in a live run, where
  /// that is how a run ends).
  int interrupted_by = 0;
  /// Files written, in the order written.
  std::vector<std::string> files;
  std::vector<ExpectationResult> expectations;
  /// Simulation::warning_lines() at the end of the run.
  std::vector<std::string> warnings;
  bool all_expectations_met() const;
};

/// "scenario.toml:LINE: ", the start of a message about that line of `scenario`.
inline std::string scenario_place(const scenario::Scenario& scenario, int line) {
  return scenario.file + ":" + std::to_string(line) + ": ";
}

}  // namespace stepdance::sim
