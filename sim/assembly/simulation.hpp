// A whole simulation built from a scenario: boards, devices, sockets, machine, cables, outputs, checks.
#pragma once

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "board/host/board_source.hpp"
#include "board/host/sim_board.hpp"
#include "kinds/sim_device.hpp"
#include "models/machine.hpp"
#include "models/servo_board.hpp"
#include "models/stepper_driver.hpp"
#include "output/picture_writer.hpp"
#include "output/summary_writer.hpp"
#include "scenario/scenario.hpp"
#include "kernel/scheduler/one_shot_pool.hpp"
#include "kernel/scheduler/periodic_timer.hpp"
#include "kernel/scheduler/scheduler.hpp"
#include "assembly/cable_link.hpp"
#include "assembly/csv_sampler.hpp"
#include "assembly/expectations.hpp"
#include "assembly/host_client.hpp"
#include "assembly/output_plan.hpp"
#include "assembly/pulse_delivery.hpp"
#include "assembly/vcd_recorder.hpp"

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

/// Builds everything a scenario describes and runs it:
///
///   timeline ─► encoder/pot/button models ─► board inputs (read when the sketch reads them)
///   board output ports ─► stepper / servo models ─► machine ─► pen strokes ─► SVG / PNG
///                     └─► cables ─► other boards' input ports
///                     └─► VCD
///   every csv_interval ─► CSV row;  at the end ─► summary JSON, [[expect]] checks
///
/// Deterministic: the same scenario, sketches and options give byte-identical files (the
/// summary's last key, wall_time_s, aside).
class Simulation {
 public:
  /// Compiles and loads every sketch and wires the scenario up. Returns null and fills `error`
  /// when something is wrong.
  static std::unique_ptr<Simulation> create(const scenario::Scenario& scenario, const SimulationOptions& options,
                                            SimulationError& error);
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  /// Runs from the current time up to `end_ns` (at most the duration). Context: not re-entrant.
  void run_until(SimTime end_ns);
  /// Runs to the end, writes every output file and evaluates the expectations. Output failures
  /// throw std::runtime_error("path: …").
  SimulationReport finish();
  /// Makes the current time the end of the run (a live run interrupted by the user), so
  /// finish() writes everything up to now. Context: between run_until() calls.
  void end_now();
  /// Calls `tick` with the time every `period_ns` of simulated time from now on, wherever the
  /// run is, a sketch's delay() included: the live front end exchanges bytes with its terminals
  /// and paces to the wall clock there. A stop request seen after a tick (Ctrl-C) stops the run.
  /// One pacer per simulation; a second call replaces the first.
  void pace_every(SimTime period_ns, std::function<void(SimTime)> tick);

  // ---- what tests and tools look at ----
  SimTime now() const { return scheduler_.now(); }
  SimTime duration() const { return duration_; }
  /// Whether the run was stopped before its end (a stopped sketch, an interrupt).
  bool stopped() const { return scheduler_.stopped(); }
  /// A board by name (null if none).
  SimBoard* board(const std::string& name) const;
  /// The stepper / servo in `board`'s socket `port` (null if none).
  const StepperDriver* stepper(const std::string& board, char port) const;
  const ServoBoard* servo(const std::string& board, char port) const;
  /// The machine (null if the scenario has none).
  const Machine* machine() const { return machine_.get(); }
  /// The cables, in scenario order.
  const std::vector<std::unique_ptr<CableLink>>& cables() const { return cables_; }
  /// The scripted host client on `board` (null if none).
  const HostClient* host_client(const std::string& board) const;
  /// The [[device]] with this name (its model through model_of<T>()), or null.
  const SimDevice* device(const std::string& name) const;
  /// The same device, to schedule actions on (SimDevice::schedule, as the timeline does): the
  /// live view's inputs. Context: between run_until() calls.
  SimDevice* device(const std::string& name);
  /// The scenario being run (boards, devices, machine, output names).
  const scenario::Scenario& scenario() const { return scenario_; }
  /// The SVG document of the drawing as it stands now, on the page the run's SVG file would
  /// use (the same bytes write_drawings() would write at this instant); "" without a machine.
  std::string drawing_svg() const;
  /// The JSON summary text as it would be written now (wall time left out).
  std::string summary_text() const;
  /// One line per kind of warning on each board's fault path, with its count and the first
  /// report's detail: "[driver] warning ×3: Eibotboard: overrun (first: …)".
  std::vector<std::string> warning_lines() const;
  /// Where the replay page goes ("" = none): checked with the other outputs by create(), written
  /// by the front end after finish().
  const std::string& html_path() const { return html_path_; }

 private:
  struct Socket {
    std::unique_ptr<StepperDriver> stepper;
    std::unique_ptr<ServoBoard> servo;
    std::unique_ptr<WireListener> feeder;
  };
  struct BoardSlot {
    const scenario::BoardConfig* config = nullptr;
    std::unique_ptr<SimBoard> board;
    std::array<Socket, 4> sockets;
  };
  Simulation(const scenario::Scenario& scenario, const SimulationOptions& options);

  // Assembly, one file a concern: board_assembly.cpp (boards, sockets), machine_assembly.cpp,
  // device_assembly.cpp (devices, their timeline, their pictures), host_assembly.cpp (host
  // clients, serial input, transcripts), cable_assembly.cpp, recorder_assembly.cpp (VCD, CSV),
  // output_files.cpp (the files a run writes, checked before it), run_report.cpp (drawings,
  // summary); expectations.cpp checks the [[expect]] entries.
  bool build_boards(SimulationError& error);
  bool build_sketches(std::vector<SketchBuild>& builds, std::vector<bool>& runs_image, SimulationError& error);
  /// The firmware image `config`'s board runs ("" for its host-compiled sketch).
  std::string image_of(const scenario::BoardConfig& config) const;
  /// The board for `config`: its sketch's library (`build`) or its firmware image loaded.
  std::unique_ptr<SimBoard> make_board(const scenario::BoardConfig& config, const SketchBuild& build,
                                       SimulationError& error);
  void add_storage_violations(SimulationReport& report) const;
  bool check_module(const BoardSlot& slot, SimulationError& error) const;
  void build_sockets(BoardSlot& slot);
  bool build_machine(SimulationError& error);
  void build_devices();
  void apply_timeline();
  void build_hosts();
  void build_cables();
  void build_vcd();
  void build_csv();
  void write_device_outputs(SimulationReport& report);
  void write_transcripts(SimulationReport& report) const;
  BoardSlot& slot(const std::string& name);
  const BoardSlot* find_slot(const std::string& name) const;
  /// "scenario.toml:LINE: ", the start of a message about that line.
  std::string place(int line) const;
  /// A configured output file's path, moved into --out's directory when that was given.
  std::string output_path(const std::string& configured) const;
  /// Every file and folder the run will write, and who asked for it (output_plan.hpp).
  std::vector<PlannedOutput> output_files() const;
  /// Checks the outputs against each other and the scenario's inputs (output_plan.hpp), then
  /// creates the folders of every output file and checks that each can be written, before any
  /// sketch is built; false with a kBadInput error naming the line, option or folder otherwise.
  bool prepare_outputs(SimulationError& error) const;
  /// The lines the VCD records: the scenario's vcd_ports, or everything (see vcd_file).
  std::vector<scenario::PortLineRef> vcd_ports() const;
  /// The key of a recorded input port in vcd_inputs_: "board:IN_A".
  static std::string vcd_input_key(const std::string& board, char port);

  // Running.
  static void on_serial_action(void* context, SimTime time, const size_t& action_index);
  /// A board's sketch was stopped: the run ends now (the first stop is the one reported).
  void on_sketch_stop(const SketchStop& stop);
  /// Whether the run was stopped before its end (a sketch stop, an interrupt); ends it now if so.
  bool stopped_early();
  /// Why the expectations cannot be checked, or "" when they can.
  std::string unchecked_reason() const;
  /// Shows every board's unfinished console line (printed without a newline).
  void flush_console_lines();
  void after_frames(SimTime frame_start_ns);
  void update_machine(SimTime time_ns);

  // Reporting (run_report.cpp).
  /// The machine's strokes as drawn (shaded pieces, on the page's coordinates) and their style.
  DrawingStyle drawing_now(std::vector<Stroke>& strokes) const;
  void write_drawings(SimulationReport& report) const;
  RunSummary run_summary() const;
  nlohmann::json summary_extra() const;
  void add_board_extras(nlohmann::json& extra) const;
  void add_firmware_extras(nlohmann::json& extra) const;
  nlohmann::json cable_extras() const;
  nlohmann::json machine_extra() const;
  void write_summary_file(const SimulationReport& report) const;

  scenario::Scenario scenario_;
  SimulationOptions options_;
  SimTime duration_ = 0;
  std::optional<SketchStop> sketch_stop_;
  int interrupted_by_ = 0;
  std::string output_directory_;
  std::string vcd_path_;  ///< "" = no VCD
  std::string html_path_;  ///< "" = no replay page
  std::string csv_path_;  ///< "" = no CSV

  Scheduler scheduler_;
  std::vector<BoardSlot> boards_;
  std::unique_ptr<Machine> machine_;
  bool machine_moved_ = false;
  uint32_t ticks_since_machine_update_ = 0;
  SimTime machine_time_ns_ = 0;

  /// Every [[device]] by name, whatever its kind (kinds/sim_device.hpp).
  std::map<std::string, std::unique_ptr<SimDevice>> devices_;

  PulseDelivery delivery_;
  std::vector<std::unique_ptr<CableLink>> cables_;
  std::unique_ptr<VcdRecorder> vcd_;
  std::map<std::string, size_t> vcd_inputs_;  ///< "board:IN_A" → recorder input
  std::unique_ptr<CsvSampler> csv_;
  OneShotPool<size_t> serial_actions_;
  std::vector<std::unique_ptr<HostClient>> hosts_;
  std::function<void(SimTime)> pacer_;
  std::unique_ptr<PeriodicTimer> pacer_timer_;
  double wall_s_ = 0;
};

}  // namespace stepdance::sim
