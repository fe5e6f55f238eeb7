// The live simulator: a run paced to the wall clock, each board's USB serial on a pseudo-terminal.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "assembly/simulation.hpp"
#include "view/run_control.hpp"

namespace stepdance::cli {

/// A page watching a live run (`--view`; cli/view/live_view_server.hpp): it is given every
/// console byte, gets a turn at every exchange with the terminals, and waits in place of the
/// pacing's sleeps so that it answers its pages while the run waits for the wall clock.
class LiveView {
 public:
  virtual ~LiveView() = default;
  /// The line announced on stdout beside the terminals: "view: http://127.0.0.1:PORT/?token=…".
  virtual std::string announcement() const = 0;
  /// Bytes board `board` printed on its USB serial.
  virtual void console(const std::string& board, const uint8_t* data, size_t length) = 0;
  /// Handles what the pages sent (inputs reach the simulation here) and sends the updates
  /// due at wall time `wall_s`, without waiting.
  virtual void serve_now(double wall_s) = 0;
  /// The same, for up to `span` of wall time (the pacing's sleep).
  virtual void serve_for(std::chrono::steady_clock::duration span) = 0;
  /// Pause and speed, as the pages set them.
  virtual sim::view::RunControl& control() = 0;
  /// The run is over: a last update to every page, then the connections close.
  virtual void finish() = 0;
};

/// How a live run is paced and where its ports appear.
struct LiveOptions {
  /// Simulated seconds per wall-clock second; 0 runs as fast as possible.
  double speed = 1.0;
  /// Board name → a symlink to create to that board's terminal.
  std::map<std::string, std::string> serial_links;
  /// The page watching the run, if any (then its RunControl's speed paces the run).
  LiveView* view = nullptr;
  /// Also called at every exchange with the terminals (the replay recorder), if set.
  std::function<void(sim::SimTime)> on_tick;
  /// Also given every console byte (the replay recorder), if set.
  std::function<void(const std::string& board, const uint8_t* data, size_t length)> on_console;
};

/// A live run's wall-clock time, and the part of it spent computing (not waiting for the clock).
struct LiveTiming {
  double wall_s = 0;
  double computing_s = 0;
  /// The pacing error: at each paced simulated millisecond (a speed other than max, not
  /// paused), how far simulated time was behind the wall clock before the run waited for it
  /// (ms of wall time; 0 when it was ahead). Their count, largest and mean.
  uint64_t paced_ms = 0;
  double lag_max_ms = 0;
  double lag_mean_ms = 0;
  /// Wall time the run gave up instead of catching up (LivePacer): by this much the run went
  /// slower than `speed` times the wall clock, ms.
  double given_up_ms = 0;
};

/// Opens a terminal per board and announces each on stdout, exactly `serial <board>: <path>`,
/// flushed, before simulated time starts. Then runs the simulation until SIGINT or SIGTERM (or
/// the end of its duration, or a stopped sketch), moving bytes between terminals and sketches
/// every simulated millisecond and pacing to the wall clock (late by more than
/// LivePacer::kCatchUpLimit, it gives the time up and runs slower than the clock rather than
/// racing a client that was slowed by the same load; and a client that drives its board gets up
/// to 100 ms to read the board's output before simulated time goes on), and finally makes the current time
/// the end of the run (Simulation::end_now). Needs a Containment in scope for the signals.
/// Returns how long it took. Throws std::runtime_error when a terminal or link cannot be made.
LiveTiming run_live(sim::Simulation& simulation, const std::vector<std::string>& boards, const LiveOptions& options);

}  // namespace stepdance::cli
