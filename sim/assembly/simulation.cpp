// Simulation: creation order, the run loop, stopping early, the end of a run and lookups. What
// each part of a run is built from has its own file (simulation.hpp lists them).
#include "assembly/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

namespace stepdance::sim {
namespace {

/// The run advances in slices of this much simulated time, flushing the VCD and reporting
/// progress between them.
constexpr SimTime kSliceNs = 10 * kMillisecond;

}  // namespace

bool SimulationReport::all_expectations_met() const {
  return std::all_of(expectations.begin(), expectations.end(), [](const ExpectationResult& r) { return r.met; });
}

Simulation::Simulation(const scenario::Scenario& scenario, const SimulationOptions& options)
    : scenario_(scenario),
      options_(options),
      duration_(options.duration.value_or(scenario.duration)),
      output_directory_(options.output_directory.value_or(scenario.output.directory)),
      delivery_(scheduler_),
      serial_actions_(scheduler_, &on_serial_action, this) {
  vcd_path_ = options.vcd_file.value_or(output_path(scenario.output.vcd));
  if (!options.write_vcd) vcd_path_.clear();
  csv_path_ = options.csv_file.value_or(output_path(scenario.output.csv));
  html_path_ = options.html_file.value_or(output_path(scenario.output.html));
  if (options.csv_interval_ms) scenario_.output.csv_interval_ms = *options.csv_interval_ms;
}

Simulation::~Simulation() {
  csv_.reset();
  hosts_.clear();
  cables_.clear();
  boards_.clear();  // unloads the sketches while the scheduler and models still exist
}

std::unique_ptr<Simulation> Simulation::create(const scenario::Scenario& scenario, const SimulationOptions& options,
                                               SimulationError& error) {
  std::unique_ptr<Simulation> simulation(new Simulation(scenario, options));
  if (!simulation->prepare_outputs(error)) return nullptr;
  if (!simulation->build_boards(error) || !simulation->build_machine(error)) return nullptr;
  simulation->build_devices();
  simulation->apply_timeline();
  simulation->build_hosts();
  try {
    simulation->build_vcd();
    simulation->build_cables();
    simulation->build_csv();
  } catch (const std::exception& failure) {
    error = {SimulationError::kFailure, failure.what()};
    return nullptr;
  }
  for (BoardSlot& slot : simulation->boards_) {
    slot.board->set_end_time(simulation->duration_);
    slot.board->power_on(0);
  }
  return simulation;
}

// ---- running ------------------------------------------------------------------------------------

void Simulation::run_until(SimTime end_ns) {
  const SimTime end = std::min(end_ns, duration_);
  const auto started = std::chrono::steady_clock::now();
  while (!stopped_early()) {
    const SimTime slice_end = std::min(end, scheduler_.now() + kSliceNs);
    scheduler_.run_until(slice_end);
    if (vcd_) vcd_->flush(std::min(slice_end, scheduler_.now()));
    if (options_.progress) options_.progress(std::min(slice_end, scheduler_.now()), duration_);
    if (slice_end >= end) break;
  }
  wall_s_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
}

// ---- stopping early -------------------------------------------------------------------------------

namespace {
std::string seconds_text(SimTime time_ns) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6f s", to_seconds(time_ns));
  return text;
}
}  // namespace

void Simulation::on_sketch_stop(const SketchStop& stop) {
  if (!sketch_stop_) sketch_stop_ = stop;
}

bool Simulation::stopped_early() {
  if (EntryMonitor::requested() == EscapeCause::kInterrupted && interrupted_by_ == 0) {
    interrupted_by_ = EntryMonitor::requested_detail();
    scheduler_.stop();
  }
  if (!scheduler_.stopped()) return false;
  if (duration_ > scheduler_.now()) end_now();
  return true;
}

std::string Simulation::unchecked_reason() const {
  if (sketch_stop_ && !(options_.live && sketch_stop_->cause == EscapeCause::kInterrupted)) {
    return "the run was stopped (" + sketch_stop_->message() + ")";
  }
  if (interrupted_by_ != 0 && !options_.live) return "the run was interrupted at t = " + seconds_text(scheduler_.now());
  return "";
}

void Simulation::pace_every(SimTime period_ns, std::function<void(SimTime)> tick) {
  pacer_ = std::move(tick);
  pacer_timer_ = std::make_unique<PeriodicTimer>(
      scheduler_,
      [](void* context, SimTime time) {
        auto& simulation = *static_cast<Simulation*>(context);
        simulation.pacer_(time);
        simulation.stopped_early();
      },
      this);
  pacer_timer_->start(scheduler_.now() + period_ns, period_ns);
}

void Simulation::flush_console_lines() {
  for (BoardSlot& slot : boards_) slot.board->flush_console_line();
}

void Simulation::end_now() {
  duration_ = scheduler_.now();
  for (BoardSlot& slot : boards_) slot.board->set_end_time(duration_);
  if (vcd_) vcd_->set_end_time(duration_);
}

SimulationReport Simulation::finish() {
  run_until(duration_);
  flush_console_lines();
  if (machine_) update_machine(duration_);
  SimulationReport report;
  report.simulated_ns = scheduler_.now();
  report.wall_s = wall_s_;
  report.sketch_stop = sketch_stop_;
  report.interrupted_by = options_.live ? 0 : interrupted_by_;
  if (vcd_) {
    vcd_->close(duration_);
    report.files.push_back(vcd_path_);
  }
  if (csv_) {
    csv_->close();
    report.files.push_back(csv_path_);
  }
  write_drawings(report);
  write_device_outputs(report);
  write_transcripts(report);
  if (!scenario_.output.summary.empty()) {
    write_summary_file(report);
    report.files.push_back(output_path(scenario_.output.summary));
  }
  const std::string unchecked = unchecked_reason();
  report.expectations =
      unchecked.empty() ? evaluate_expectations(scenario_, *this) : unchecked_expectations(scenario_, unchecked);
  add_storage_violations(report);
  report.warnings = warning_lines();
  return report;
}

// Storage touched from an interrupt fails the run, whatever the scenario expects: on the board
// a card access can take far longer than a frame.
void Simulation::add_storage_violations(SimulationReport& report) const {
  for (const BoardSlot& slot : boards_) {
    const uint64_t calls = slot.board->storage_calls_in_isr();
    if (calls == 0) continue;
    report.expectations.push_back({false, "board '" + slot.config->name + "': the sketch touched the SD card " +
                                              std::to_string(calls) +
                                              " times from the frame or kilohertz interrupt (storage is loop-only)"});
  }
}

// ---- lookups ------------------------------------------------------------------------------------

std::string Simulation::place(int line) const { return scenario_.file + ":" + std::to_string(line) + ": "; }

std::string Simulation::output_path(const std::string& configured) const {
  if (configured.empty() || !options_.output_directory) return configured;
  return (std::filesystem::path(*options_.output_directory) / std::filesystem::path(configured).filename()).string();
}

Simulation::BoardSlot& Simulation::slot(const std::string& name) { return const_cast<BoardSlot&>(*find_slot(name)); }

const Simulation::BoardSlot* Simulation::find_slot(const std::string& name) const {
  for (const BoardSlot& slot : boards_) {
    if (slot.config->name == name) return &slot;
  }
  return nullptr;
}

SimBoard* Simulation::board(const std::string& name) const {
  const BoardSlot* found = find_slot(name);
  return found != nullptr ? found->board.get() : nullptr;
}

const StepperDriver* Simulation::stepper(const std::string& board, char port) const {
  const BoardSlot* found = find_slot(board);
  if (found == nullptr || port < 'A' || port > 'D') return nullptr;
  return found->sockets[port - 'A'].stepper.get();
}

const ServoBoard* Simulation::servo(const std::string& board, char port) const {
  const BoardSlot* found = find_slot(board);
  if (found == nullptr || port < 'A' || port > 'D') return nullptr;
  return found->sockets[port - 'A'].servo.get();
}

}  // namespace stepdance::sim
