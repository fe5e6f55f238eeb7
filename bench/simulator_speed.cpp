// Simulator benchmark: Step-A-Sketch speed (simulated s per wall s), per-frame overhead against
// the bare engine measured in the same process, and peak memory over 10 simulated minutes.
//
//   stepdance_simulator_speed [runs]       wall-clock figures, each the best of `runs` (default 5)
//   stepdance_simulator_speed --simulate   one run of the scenario, nothing printed
//   stepdance_simulator_speed --engine N   N frames of the bare engine, nothing printed
// The last two exist for callgrind (bench/measure_simulator.sh), whose instruction counts repeat
// exactly where wall-clock time does not. Not a test: it reports numbers and asserts nothing.
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "assembly/simulation.hpp"
#include "board/loader/sketch_builder.hpp"
#include "scenario/load_scenario.hpp"
#include "step_a_sketch_graph.hpp"

namespace {

using Clock = std::chrono::steady_clock;
using stepdance::sim::SimTime;
using stepdance::sim::Simulation;
namespace scenario = stepdance::sim::scenario;

constexpr SimTime kFrameNs = 40 * stepdance::sim::kMicrosecond;
constexpr uint32_t kBareFrames = 2000000;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

scenario::Scenario step_a_sketch() {
  const scenario::LoadResult loaded = scenario::load_scenario(STEPDANCE_SOURCE_DIR "/examples/StepASketch");
  if (!loaded.ok()) {
    std::fprintf(stderr, "%s", loaded.error_text().c_str());
    std::exit(2);
  }
  return loaded.scenario;
}

std::unique_ptr<Simulation> make(const scenario::Scenario& scenario, SimTime duration) {
  stepdance::sim::SimulationOptions options;
  options.boards = std::make_shared<stepdance::sim::SketchBuilder>(STEPDANCE_BUILD_DIR "/sketch-cache");
  options.duration = duration;
  options.write_vcd = false;
  stepdance::sim::SimulationError error;
  auto simulation = Simulation::create(scenario, options, error);
  if (!simulation) {
    std::fprintf(stderr, "%s\n", error.message.c_str());
    std::exit(1);
  }
  return simulation;
}

/// Wall seconds to simulate the whole scenario (outputs are not written: only the run counts).
double time_simulation(const scenario::Scenario& scenario) {
  auto simulation = make(scenario, scenario.duration);
  const Clock::time_point start = Clock::now();
  simulation->run_until(scenario.duration);
  return seconds_since(start);
}

/// Wall seconds for kBareFrames frames of the same block graph on the manual backend.
double time_bare_engine() {
  stepdance::workloads::StepASketchGraph graph;
  const Clock::time_point start = Clock::now();
  for (uint32_t frame = 0; frame < kBareFrames; ++frame) graph.run_busy_frame(frame);
  return seconds_since(start);
}

/// The scenario's timeline repeated back to back until `duration`, so the whole span is busy.
scenario::Scenario repeated(scenario::Scenario scenario, SimTime duration) {
  const std::vector<scenario::Action> once = scenario.timeline;
  for (SimTime offset = scenario.duration; offset + scenario.duration <= duration; offset += scenario.duration) {
    for (scenario::Action action : once) {
      action.time += offset;
      scenario.timeline.push_back(action);
    }
  }
  scenario.duration = duration;
  scenario.expectations.clear();
  return scenario;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "--engine") {
    stepdance::workloads::StepASketchGraph graph;
    const uint32_t frames = argc > 2 ? static_cast<uint32_t>(std::atol(argv[2])) : kBareFrames;
    for (uint32_t frame = 0; frame < frames; ++frame) graph.run_busy_frame(frame);
    return 0;
  }
  const scenario::Scenario scenario = step_a_sketch();
  if (mode == "--simulate") {
    time_simulation(scenario);
    return 0;
  }
  const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  make(scenario, scenario.duration);  // compiles the sketch into the cache before timing

  double simulation_s = 1e9, bare_s = 1e9;
  for (int run = 0; run < runs; ++run) {
    simulation_s = std::min(simulation_s, time_simulation(scenario));
    bare_s = std::min(bare_s, time_bare_engine());
  }
  const double simulated_s = stepdance::sim::to_seconds(scenario.duration);
  const double frames = static_cast<double>(scenario.duration / kFrameNs);
  const double simulation_ns = simulation_s * 1e9 / frames;
  const double bare_ns = bare_s * 1e9 / kBareFrames;
  std::printf("Step-A-Sketch scenario, %.0f s simulated, VCD off (best of %d runs)\n", simulated_s, runs);
  std::printf("  wall time                   %.3f s\n", simulation_s);
  std::printf("  speed                       %.0fx real time\n", simulated_s / simulation_s);
  std::printf("  simulation per frame        %.0f ns (%.0f frames)\n", simulation_ns, frames);
  std::printf("bare engine, same block graph on the manual backend (best of %d x %u frames)\n", runs, kBareFrames);
  std::printf("  engine per frame            %.0f ns\n", bare_ns);
  std::printf("simulator overhead per frame  %.0f ns = %.2fx the bare engine's cost\n", simulation_ns - bare_ns,
              (simulation_ns - bare_ns) / bare_ns);

  const SimTime ten_minutes = 600 * stepdance::sim::kSecond;
  auto long_run = make(repeated(scenario, ten_minutes), ten_minutes);
  const Clock::time_point start = Clock::now();
  long_run->run_until(ten_minutes);
  const double long_s = seconds_since(start);
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  std::printf("10 simulated minutes (the drawing %d times over): %.1f s wall, max RSS %.1f MB\n",
              static_cast<int>(ten_minutes / scenario.duration), long_s, usage.ru_maxrss / 1024.0);
  return 0;
}
