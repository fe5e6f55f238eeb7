// Keeps the `stepdance` command in charge of the sketches it runs: crash and exit signals, Ctrl-C
// and SIGTERM, and a wall-clock watchdog (docs/simulator.md, "A sketch cannot take the simulator
// down").
#pragma once

#include <atomic>
#include <thread>

namespace stepdance::cli {

/// While it lives, on the calling thread (the one that runs the simulation):
///  - a crash in a sketch's code (SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGTRAP), a stack
///    overflow included, leaves that board's entry point and stops the run there, with a
///    backtrace; the same signals from the simulator's own code still end the process;
///  - SIGINT and SIGTERM stop the run at the next event, or leave the sketch's code if it is
///    running, so the outputs are written;
///  - a watchdog thread stops a sketch that runs `hang_budget_s` seconds of wall time without
///    simulated time moving (a busy loop, a wait that never ends) and, if a stop cannot reach the
///    sketch (it is inside a C library call that never returns), ends the process after a grace
///    period with the sketch-hung or interrupted status.
/// One at a time per process.
class Containment {
 public:
  /// `hang_budget_s` > 0; `grace_s`: how long a requested stop may take before the process ends.
  explicit Containment(double hang_budget_s, double grace_s = 2.0);
  ~Containment();
  Containment(const Containment&) = delete;
  Containment& operator=(const Containment&) = delete;

 private:
  void watch();

  double hang_budget_s_;
  double grace_s_;
  std::atomic<bool> done_{false};
  std::thread watchdog_;
};

}  // namespace stepdance::cli
