// Simulation: the order its parts are built in, the run loop, stopping early, the end of a run and
// its summary. Each part owns its state in its own file (simulation.hpp lists them).
#include "assembly/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "assembly/board_plug.hpp"
#include "assembly/board_summary.hpp"

namespace stepdance::sim {
namespace {

/// The run advances in slices of this much simulated time, flushing the VCD and reporting
/// progress between them.
constexpr SimTime kSliceNs = 10 * kMillisecond;

std::string seconds_text(SimTime time_ns) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6f s", to_seconds(time_ns));
  return text;
}

}  // namespace

bool SimulationReport::all_expectations_met() const {
  return std::all_of(expectations.begin(), expectations.end(), [](const ExpectationResult& r) { return r.met; });
}

Simulation::Simulation(const scenario::Scenario& scenario, const SimulationOptions& options)
    : scenario_(scenario),
      options_(options),
      duration_(options.duration.value_or(scenario.duration)),
      outputs_(scenario_, options_),
      boards_(scheduler_, options_, machine_.motion_flag()),
      cables_(scheduler_),
      recorders_(scheduler_),
      hosts_(scheduler_, scenario_, boards_) {
  if (options.csv_interval_ms) scenario_.output.csv_interval_ms = *options.csv_interval_ms;
}

Simulation::~Simulation() {
  recorders_.stop_csv();
  hosts_.clear();
  cables_.clear();
  boards_.clear();  // unloads the sketches while the scheduler and models still exist
}

std::unique_ptr<Simulation> Simulation::create(const scenario::Scenario& scenario, const SimulationOptions& options,
                                               SimulationError& error) {
  std::unique_ptr<Simulation> simulation(new Simulation(scenario, options));
  if (!simulation->build(error)) return nullptr;
  simulation->boards_.power_on(simulation->duration_);
  return simulation;
}

bool Simulation::build(SimulationError& error) {
  if (!outputs_.prepare(duration_, error)) return false;
  if (!boards_.build(
          scenario_, outputs_.directory(), outputs_.planned(), [this](const SketchStop& stop) { on_sketch_stop(stop); },
          error) ||
      !machine_.build(scenario_, boards_, error)) {
    return false;
  }
  devices_.build(scenario_, boards_, [this] { return machine_.machine(); });
  apply_timeline();
  hosts_.build();
  try {
    recorders_.build_vcd(outputs_.vcd_path(), outputs_.vcd_ports(), duration_, boards_);
    cables_.build(scenario_.cables, boards_, recorders_);
    recorders_.build_csv(outputs_.csv_path(), scenario_.output.csv_interval_ms, machine_.machine(), boards_, devices_);
  } catch (const std::exception& failure) {
    error = {SimulationError::kFailure, failure.what()};
    return false;
  }
  return true;
}

void Simulation::apply_timeline() {
  for (size_t index = 0; index < scenario_.timeline.size(); ++index) {
    const scenario::Action& action = scenario_.timeline[index];
    if (action.type == scenario::ActionType::kSerial) {
      hosts_.post_serial(index);
    } else {
      devices_.schedule(action);
    }
  }
}

// ---- running ------------------------------------------------------------------------------------

void Simulation::run_until(SimTime end_ns) {
  const SimTime end = std::min(end_ns, duration_);
  const auto started = std::chrono::steady_clock::now();
  while (!stopped_early()) {
    const SimTime slice_end = std::min(end, scheduler_.now() + kSliceNs);
    scheduler_.run_until(slice_end);
    recorders_.flush(std::min(slice_end, scheduler_.now()));
    if (options_.progress) options_.progress(std::min(slice_end, scheduler_.now()), duration_);
    if (slice_end >= end) break;
  }
  wall_s_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
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

// ---- stopping early -------------------------------------------------------------------------------

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

void Simulation::end_now() {
  duration_ = scheduler_.now();
  boards_.set_end_time(duration_);
  recorders_.set_end_time(duration_);
}

// ---- the end of a run -----------------------------------------------------------------------------

SimulationReport Simulation::finish() {
  run_until(duration_);
  boards_.flush_console_lines();
  if (machine_.machine() != nullptr) machine_.update(duration_);
  SimulationReport report;
  report.simulated_ns = scheduler_.now();
  report.wall_s = wall_s_;
  report.sketch_stop = sketch_stop_;
  report.interrupted_by = options_.live ? 0 : interrupted_by_;
  write_outputs(report);
  const std::string unchecked = unchecked_reason();
  report.expectations =
      unchecked.empty() ? evaluate_expectations(scenario_, *this) : unchecked_expectations(scenario_, unchecked);
  boards_.add_storage_violations(report.expectations);
  report.warnings = warning_lines();
  return report;
}

void Simulation::write_outputs(SimulationReport& report) {
  recorders_.close(duration_, report.files);
  machine_.write_drawings(outputs_.path_of(scenario_.output.svg), outputs_.path_of(scenario_.output.png),
                          options_.pictures.get(), scenario_.output.png_px_per_mm, report.files);
  write_device_outputs(report);
  hosts_.write_transcripts([this](const std::string& name) { return outputs_.path_of(name); }, report.files);
  if (!scenario_.output.summary.empty()) {
    write_summary_file(report);
    report.files.push_back(outputs_.path_of(scenario_.output.summary));
  }
}

void Simulation::write_device_outputs(SimulationReport& report) {
  const std::string directory = scenario_.output.directory;
  if (directory.empty() && !options_.output_directory) return;  // no output folder: no pictures
  if (!options_.pictures) return;                               // no picture writer
  PictureFileSink sink(
      *options_.pictures,
      [this, &directory](const std::string& file) {
        return outputs_.path_of((std::filesystem::path(directory) / file).string());
      },
      report.files);
  devices_.write_outputs(sink);
}

std::vector<std::string> Simulation::warning_lines() const { return board_warning_lines(boards_); }

// ---- the summary --------------------------------------------------------------------------------

RunSummary Simulation::run_summary() const {
  RunSummary summary;
  summary.simulated_time = scheduler_.now();
  add_port_summaries(boards_, summary);
  summary.extra = summary_extra();
  return summary;
}

nlohmann::json Simulation::summary_extra() const {
  nlohmann::json extra = nlohmann::json::object();
  add_board_extras(boards_, extra);
  extra["cables"] = cables_.summary(scenario_.cables);
  if (machine_.machine() != nullptr) extra["machine"] = machine_.summary();
  // A stopped run says so: its figures are those of the moment it stopped.
  if (sketch_stop_) {
    extra["stopped"] = {{"board", sketch_stop_->board},
                        {"entry", describe(sketch_stop_->entry)},
                        {"what", sketch_stop_->what},
                        {"time_s", to_seconds(sketch_stop_->time_ns)},
                        {"backtrace", sketch_stop_->backtrace}};
  } else if (interrupted_by_ != 0 && !options_.live) {
    extra["stopped"] = {{"what", interrupted_by_ == 15 ? "SIGTERM" : "SIGINT"},
                        {"time_s", to_seconds(scheduler_.now())}};
  }
  return extra;
}

std::string Simulation::summary_text() const { return sim::summary_text(run_summary()); }

void Simulation::write_summary_file(const SimulationReport& report) const {
  RunSummary summary = run_summary();
  summary.wall_time_s = report.wall_s;
  const std::string path = outputs_.path_of(scenario_.output.summary);
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  write_summary(path, summary);
}

}  // namespace stepdance::sim
