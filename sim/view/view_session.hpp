// One page's view of a running Simulation: the view protocol's messages out, its inputs in.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "assembly/simulation.hpp"
#include "view/run_control.hpp"
#include "view/stroke_stream.hpp"

namespace stepdance::sim::view {

/// The protocol's version, sent in "hello"; a page refuses a version it does not know.
constexpr int kProtocolVersion = 1;
/// At most this many updates per second of wall time, whatever the frame rate.
constexpr double kMaxUpdatesPerSecond = 60;
/// Incoming messages longer than this are refused (an error message; the run goes on).
constexpr size_t kMaxInputBytes = 4096;
/// Points of the drawing per update at most; the rest follow in the next updates.
constexpr size_t kMaxPointsPerUpdate = 4000;
/// Console text kept per board between two updates; older bytes are dropped and counted (the
/// update's "dropped_bytes"). The drawing has no such cap: its updates wait for a page that
/// does not read (the front end makes the next update only when the last one has gone) and
/// the next one carries every point since, so no stroke is ever dropped.
constexpr size_t kMaxConsoleBytesPerUpdate = 16384;

/// One page (a WebSocket client, a Web Worker's page) attached to a running simulation. It
/// makes the view protocol's messages (docs/simulator.md, "The view protocol"), JSON text:
/// hello() once, then update() at each pacing tick (at most kMaxUpdatesPerSecond of wall time),
/// and answers the page's messages in receive(). Inputs are applied as the scenario timeline's
/// actions would be, at the simulation's current time. Nothing here knows about sockets,
/// threads or terminals. Context: the thread running the simulation, between run_until() calls.
class ViewSession {
 public:
  ViewSession(Simulation& simulation, RunControl& control);

  /// {"type": "hello", …}: what the page draws (machine, page, boards, devices, controls).
  std::string hello() const;
  /// {"type": "update", …} if at least 1/kMaxUpdatesPerSecond of wall time (`wall_s`, any
  /// monotonic origin) has passed since the last one, else nothing.
  std::optional<std::string> update(double wall_s);
  /// The update due now, whatever the time (the last one of a run, tests).
  std::string update_now();
  /// The page's message `text`: applies it and returns the replies (an error, a drawing).
  std::vector<std::string> receive(std::string_view text);
  /// Whether the last update left points of the drawing for the next (kMaxPointsPerUpdate).
  bool strokes_behind() const { return strokes_.behind(); }
  /// Bytes board `board` printed on its console (the front end passes them on).
  void console_output(const std::string& board, const uint8_t* data, size_t length);

 private:
  struct MotorState {
    std::string board;
    char port = 'A';
    int64_t last_steps = 0;
  };
  std::string apply(const nlohmann::json& message);
  std::string apply_input(const nlohmann::json& message);
  std::string apply_console(const nlohmann::json& message);
  std::string apply_run(const nlohmann::json& message);
  nlohmann::json motors_json(double dt_s);
  nlohmann::json boards_state_json() const;

  Simulation& simulation_;
  RunControl& control_;
  StrokeStream strokes_;
  std::vector<MotorState> motors_;
  std::map<std::string, std::string> console_;  ///< board → text since the last update
  std::map<std::string, uint64_t> console_dropped_;
  std::optional<double> last_update_wall_s_;
  SimTime last_update_sim_ = 0;
};

}  // namespace stepdance::sim::view
