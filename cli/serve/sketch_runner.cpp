// The sketch server's child: confine, build, run paced, report; one run and out.
#include "serve/sketch_runner.hpp"

#include <stdlib.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <memory>
#include <regex>

#include <nlohmann/json.hpp>

#include "assembly/run_result.hpp"
#include "board/loader/sketch_builder.hpp"
#include "confine/confinement.hpp"
#include "containment.hpp"
#include "exit_codes.hpp"
#include "scenario/load_scenario.hpp"
#include "serve/run_channel.hpp"
#include "serve/run_report.hpp"
#include "simulator_hooks.hpp"
#include "view/view_session.hpp"

namespace stepdance::cli::serve {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using nlohmann::json;

/// How often the simulation is paced and the page updated, in ms.
constexpr int kPacePeriodMs = 2;
/// At --speed max, the longest stretch of simulation between looks at the page, and its steps.
constexpr std::chrono::milliseconds kMaxSpeedSlice{15};
constexpr sim::SimTime kMaxSpeedStepNs = 10 * sim::kMillisecond;

/// What a build needs to read besides the run folder: the system's programs and libraries, the
/// loader's cache and the toolchain's own files.
confine::ConfinementPaths run_paths(const std::string& folder) {
  confine::ConfinementPaths paths;
  paths.read_only = {"/usr",
                     "/lib",
                     "/lib32",
                     "/lib64",
                     "/libx32",
                     "/bin",
                     "/sbin",
                     "/etc/ld.so.cache",
                     "/etc/alternatives",
                     "/dev/urandom",
                     "/dev/zero"};
  for (const std::string& path : sim::SketchBuilder::toolchain_paths()) paths.read_only.push_back(path);
  paths.read_write = {folder, "/dev/null"};
  return paths;
}

std::unique_ptr<sim::Simulation> build(const SketchRunnerOptions& options, std::string& errors) {
  const fs::path example = fs::path(options.folder) / options.example;
  sim::scenario::LoadResult loaded = sim::scenario::load_scenario((example / options.scenario).string());
  if (!loaded.ok()) {
    errors = relative_to(loaded.error_text(), example.string());
    return nullptr;
  }
  loaded.scenario.hosts.clear();  // the page is the host here
  sim::SimulationOptions sim_options;
  plug_front_end(sim_options,
                 options.unconfined ? options.cache_directory : (fs::path(options.folder) / "cache").string());
  sim_options.output_directory = (fs::path(options.folder) / "out").string();
  sim_options.write_vcd = false;
  sim::SimulationError error;
  std::unique_ptr<sim::Simulation> simulation = sim::Simulation::create(loaded.scenario, sim_options, error);
  if (!simulation) errors = relative_to(error.message, example.string());
  return simulation;
}

/// The run as the page paces it (pause, speed) against the wall clock.
struct Pacing {
  Clock::time_point anchor_wall;
  sim::SimTime anchor_sim = 0;
  double anchor_speed = -1;
};

void pace(sim::Simulation& simulation, const sim::view::RunControl& control, Pacing& pacing) {
  const Clock::time_point now = Clock::now();
  if (control.paused) {
    pacing.anchor_speed = -1;  // paced from where it resumes
    return;
  }
  if (pacing.anchor_speed != control.speed) pacing = {now, simulation.now(), control.speed};
  if (control.speed > 0) {
    const double due_s = std::chrono::duration<double>(now - pacing.anchor_wall).count() * control.speed;
    simulation.run_until(std::min(simulation.duration(), pacing.anchor_sim + sim::from_seconds(due_s)));
    return;
  }
  while (Clock::now() - now < kMaxSpeedSlice && simulation.now() < simulation.duration() && !simulation.stopped())
    simulation.run_until(std::min(simulation.duration(), simulation.now() + kMaxSpeedStepNs));
}

bool over(const sim::Simulation& simulation) {
  return simulation.now() >= simulation.duration() || simulation.stopped();
}

// Runs to the end (or until the server goes away), then sends `ended` for a stopped sketch and
// the result. Returns the exit status.
int run(sim::Simulation& simulation, RunChannel& channel, const SketchRunnerOptions& options) {
  sim::view::RunControl control;
  sim::view::ViewSession session(simulation, control);
  for (const auto& board : simulation.scenario().boards) {
    const std::string name = board.name;
    simulation.board(name)->console().on_bytes(
        [&session, name](const uint8_t* data, size_t length) { session.console_output(name, data, length); });
  }
  channel.send(json{{"type", "started"}}.dump());
  channel.send(session.hello());
  Pacing pacing;
  bool connected = true;
  while (connected && !over(simulation)) {
    connected = channel.receive(kPacePeriodMs, [&](std::string_view text) {
      for (const std::string& reply : session.receive(text)) channel.send(reply);
    });
    pace(simulation, control, pacing);
    const double wall_s = std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
    if (auto update = session.update(wall_s)) channel.send(*update);
  }
  if (!connected) return kExitSignalBase + SIGTERM;
  channel.send(session.update_now());
  const sim::SimulationReport report = simulation.finish();
  const fs::path example = fs::path(options.folder) / options.example;
  if (report.sketch_stop) channel.send(ended_message(*report.sketch_stop, example.string()).dump());
  json result = json::parse(sim::run_result_json(simulation, report));
  channel.send(json{{"type", "result"}, {"result", result}}.dump());
  return stop_exit_status(report);
}

}  // namespace

int run_sketch_runner(const SketchRunnerOptions& options) {
  RunChannel channel(options.channel_fd);
  if (!options.unconfined) {
    const std::string problem = confine::confine_process(run_paths(options.folder), confine::ConfinementLimits{});
    if (!problem.empty()) {
      channel.send(json{{"type", "failed"}, {"text", "the run could not be confined: " + problem}}.dump());
      return kExitFailure;
    }
  }
  // The compiler's and addr2line's temporary files stay in the run folder too.
  setenv("TMPDIR", options.folder.c_str(), 1);
  setenv("HOME", options.folder.c_str(), 1);
  if (chdir(options.folder.c_str()) != 0) return kExitFailure;
  try {
    std::string errors;
    std::unique_ptr<sim::Simulation> simulation = build(options, errors);
    if (!simulation) {
      channel.send(json{{"type", "failed"}, {"text", errors}}.dump());
      return kExitBadInput;
    }
    Containment containment(options.watchdog_s);
    return run(*simulation, channel, options);
  } catch (const std::exception& failure) {
    channel.send(json{{"type", "error"}, {"message", std::string("the run: ") + failure.what()}}.dump());
    return kExitFailure;
  }
}

}  // namespace stepdance::cli::serve
