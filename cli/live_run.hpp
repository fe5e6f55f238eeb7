// The live simulator: a run paced to the wall clock, each board's USB serial on a pseudo-terminal.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "assembly/simulation.hpp"

namespace stepdance::cli {

/// How a live run is paced and where its ports appear.
struct LiveOptions {
  /// Simulated seconds per wall-clock second; 0 runs as fast as possible.
  double speed = 1.0;
  /// Board name → a symlink to create to that board's terminal.
  std::map<std::string, std::string> serial_links;
};

/// A live run's wall-clock time, and the part of it spent computing (not waiting for the clock).
struct LiveTiming {
  double wall_s = 0;
  double computing_s = 0;
};

/// Opens a terminal per board and announces each on stdout, exactly `serial <board>: <path>`,
/// flushed, before simulated time starts. Then runs the simulation until SIGINT or SIGTERM (or
/// the end of its duration, or a stopped sketch), moving bytes between terminals and sketches
/// every simulated millisecond and pacing to the wall clock, and finally makes the current time
/// the end of the run (Simulation::end_now). Needs a Containment in scope for the signals.
/// Returns how long it took. Throws std::runtime_error when a terminal or link cannot be made.
LiveTiming run_live(sim::Simulation& simulation, const std::vector<std::string>& boards, const LiveOptions& options);

}  // namespace stepdance::cli
