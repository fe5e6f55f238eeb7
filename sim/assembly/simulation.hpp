// A whole simulation built from a scenario: boards, devices, sockets, machine, cables, outputs, checks.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "assembly/board_set.hpp"
#include "assembly/cable_set.hpp"
#include "assembly/device_set.hpp"
#include "assembly/expectations.hpp"
#include "assembly/host_set.hpp"
#include "assembly/machine_rig.hpp"
#include "assembly/output_files.hpp"
#include "assembly/recorders.hpp"
#include "assembly/simulation_options.hpp"
#include "kernel/scheduler/periodic_timer.hpp"
#include "kernel/scheduler/scheduler.hpp"
#include "output/summary_writer.hpp"
#include "scenario/scenario.hpp"

namespace stepdance::sim {

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
///
/// It composes one object per concern, each owning its state: OutputFiles (where every file
/// goes), BoardSet (boards and their sockets), MachineRig, DeviceSet, HostSet (host clients and
/// serial input), Recorders (VCD, CSV) and CableSet. Simulation builds them in order, runs the
/// scheduler and gathers the report.
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
  SimBoard* board(const std::string& name) const { return boards_.board(name); }
  /// The stepper / servo in `board`'s socket `port` (null if none).
  const StepperDriver* stepper(const std::string& board, char port) const { return boards_.stepper(board, port); }
  const ServoBoard* servo(const std::string& board, char port) const { return boards_.servo(board, port); }
  /// The machine (null if the scenario has none).
  const Machine* machine() const { return machine_.machine(); }
  /// The cables, in scenario order.
  const std::vector<std::unique_ptr<CableLink>>& cables() const { return cables_.links(); }
  /// The scripted host client on `board` (null if none).
  const HostClient* host_client(const std::string& board) const { return hosts_.client(board); }
  /// The [[device]] with this name (its model through model_of<T>()), or null.
  const SimDevice* device(const std::string& name) const { return devices_.find(name); }
  /// The same device, to schedule actions on (SimDevice::schedule, as the timeline does): the
  /// live view's inputs. Context: between run_until() calls.
  SimDevice* device(const std::string& name) { return devices_.find(name); }
  /// The scenario being run (boards, devices, machine, output names).
  const scenario::Scenario& scenario() const { return scenario_; }
  /// The SVG document of the drawing as it stands now, on the page the run's SVG file would
  /// use (the same bytes write_drawings() would write at this instant); "" without a machine.
  std::string drawing_svg() const { return machine_.drawing_svg(); }
  /// The JSON summary text as it would be written now (wall time left out).
  std::string summary_text() const;
  /// One line per kind of warning on each board's fault path, with its count and the first
  /// report's detail: "[driver] warning ×3: Eibotboard: overrun (first: …)".
  std::vector<std::string> warning_lines() const;
  /// Where the replay page goes ("" = none): checked with the other outputs by create(), written
  /// by the front end after finish().
  const std::string& html_path() const { return outputs_.html_path(); }

 private:
  Simulation(const scenario::Scenario& scenario, const SimulationOptions& options);

  /// Builds the parts in their order (outputs checked, boards, machine, devices, timeline, hosts,
  /// VCD, cables, CSV); false with `error` filled when one cannot be built.
  bool build(SimulationError& error);
  /// Device actions go straight into the device models (their schedules are known in advance);
  /// serial input needs an event at its time.
  void apply_timeline();
  /// A board's sketch was stopped: the run ends now (the first stop is the one reported).
  void on_sketch_stop(const SketchStop& stop);
  /// Whether the run was stopped before its end (a sketch stop, an interrupt); ends it now if so.
  bool stopped_early();
  /// Why the expectations cannot be checked, or "" when they can.
  std::string unchecked_reason() const;
  /// Writes every file of the finished run, in order, into report.files.
  void write_outputs(SimulationReport& report);
  void write_device_outputs(SimulationReport& report);
  RunSummary run_summary() const;
  /// The summary's extra entries: the parts' own, and why the run stopped early, if it did.
  nlohmann::json summary_extra() const;
  void write_summary_file(const SimulationReport& report) const;

  scenario::Scenario scenario_;
  SimulationOptions options_;
  SimTime duration_ = 0;
  std::optional<SketchStop> sketch_stop_;
  int interrupted_by_ = 0;
  OutputFiles outputs_;

  Scheduler scheduler_;
  MachineRig machine_;
  BoardSet boards_;
  DeviceSet devices_;
  CableSet cables_;
  Recorders recorders_;
  HostSet hosts_;
  std::function<void(SimTime)> pacer_;
  std::unique_ptr<PeriodicTimer> pacer_timer_;
  double wall_s_ = 0;
};

}  // namespace stepdance::sim
