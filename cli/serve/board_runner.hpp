// The child process of `stepdance serve <scenario>`: the simulated board run inside a
// Containment, talking to the server over an inherited socket (the hidden `stepdance run-board`).
#pragma once

#include <string>

namespace stepdance::cli::serve {

/// What `stepdance serve` hands its board's child.
struct BoardRunnerOptions {
  std::string scenario;          ///< the scenario file or example folder
  std::string board;             ///< the board to bridge ("" = the first)
  double speed = 1.0;            ///< simulated seconds per wall second
  std::string output_directory;  ///< "" = the scenario's
  std::string cache_directory;   ///< "" = the sketch cache's default
  double watchdog_s = 10;        ///< wall seconds a sketch may run without simulated time moving
  int channel_fd = 3;
};

/// Loads the scenario and builds the simulation (errors on stderr, exit 2 or 1 as `sim`), then
/// runs the board paced to the wall clock (serve/simulated_board_link.hpp) until the server
/// closes the channel or sends SIGTERM, or its sketch is stopped. Messages to the server, one a
/// line: {"hello": machine description} once running, {"line": text} per console line,
/// {"drawing": …}, {"ended": {"text": report}} for a stopped sketch, {"wrote": [files]} last.
/// From the server: {"send": bytes} for the board's serial. Returns `sim`'s exit status.
/// Context: the child's main thread.
int run_board_runner(const BoardRunnerOptions& options);

}  // namespace stepdance::cli::serve
