// The child process of the sketch server: one run of a page's sketch, confined, talking to the
// server over an inherited socket (the hidden `stepdance run-sketch` command).
#pragma once

#include <string>

namespace stepdance::cli::serve {

/// A run the server prepared: its files are in <folder>/<example>/.
struct SketchRunnerOptions {
  std::string folder;           ///< the run folder (absolute); the only one it may write
  std::string example;          ///< the example's folder name in it
  std::string scenario;         ///< the scenario's file name in the example's folder
  double watchdog_s = 5;        ///< wall seconds a sketch may run without simulated time moving
  bool unconfined = false;      ///< skip the confinement (the server's --unconfined)
  std::string cache_directory;  ///< unconfined only: the sketch cache ("" = its default)
  int channel_fd = 3;           ///< the socket to the server: JSON messages, one a line, both ways
};

/// Confines the process (confine/confinement.hpp) to the run folder and the toolchain, then
/// reads the scenario, compiles the sketches (cached in <folder>/cache) and runs the simulation
/// paced to the wall clock inside a Containment, sending the edit protocol's messages (`failed`,
/// `started`, the view's, `ended`, `result`; docs/web.md) and taking the page's view messages on
/// the channel. Returns what `stepdance sim` would (docs/simulator.md, exit codes); when the
/// server goes away the run stops. Context: the child process's main thread, before any other.
int run_sketch_runner(const SketchRunnerOptions& options);

}  // namespace stepdance::cli::serve
