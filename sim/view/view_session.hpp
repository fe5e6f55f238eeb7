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
#include "view/sent_state.hpp"
#include "view/stroke_stream.hpp"

namespace stepdance::sim::view {

/// The protocol's version, sent in "hello"; a page refuses a version it does not know.
/// Version 2: an update carries only what changed since the last one (a delta).
constexpr int kProtocolVersion = 2;
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
///
/// Updates are deltas: each carries `t_s` and only the parts of the state (the run's pace, the
/// pen, new strokes, each motor and board, and the parts each device's and the machine's kind
/// gives: kinds/page_part.hpp) that differ from what the page was last sent, and console text
/// since. The session names no kind: it asks each device (SimDevice::add_page_parts,
/// describe_page_control) and the machine's row (MachineKind::add_page_parts). Nothing changed (a paused run): no
/// update at all. The session assumes every update it makes reaches the page; a front end that loses one calls
/// start_over(), and the next update carries the whole state again.
class ViewSession {
 public:
  ViewSession(Simulation& simulation, RunControl& control);

  /// {"type": "hello", …}: what the page draws (machine, page, boards, devices, controls).
  std::string hello() const;
  /// {"type": "update", …} if at least 1/kMaxUpdatesPerSecond of wall time (`wall_s`, any
  /// monotonic origin) has passed since the last one (or hold_back()) and anything changed,
  /// else nothing.
  std::optional<std::string> update(double wall_s);
  /// The update due now, whatever the time and even if nothing changed (then only `t_s`): the
  /// last one of a run, a replay's instant, tests.
  std::string update_now();
  /// Whether an update would be made now (1/kMaxUpdatesPerSecond since the last one).
  bool due(double wall_s) const;
  /// The front end skips a due update (its page has not read the last one yet): counted, and
  /// the next is due a period later. Nothing is lost: the next update is a delta against what
  /// the page was actually sent, so it carries everything since.
  void hold_back(double wall_s);
  /// Updates held back so far (hold_back()).
  uint64_t held_back() const { return held_back_; }
  /// Console bytes dropped so far, every board's (kMaxConsoleBytesPerUpdate).
  uint64_t console_dropped_bytes() const;
  /// Updates made so far (update() and update_now()).
  uint64_t updates_made() const { return updates_made_; }
  /// The page has lost track (it asked for hello again, or an update did not reach it): the
  /// next update carries the whole state, the drawing from its first stroke.
  void start_over();
  /// The run is over (a live run stopped by its user): updates say "ended" from now on. A run
  /// at its duration or stopped by its sketch says so without it.
  void end_run();
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
    double rate_steps_per_s = 0;
  };
  /// The update's parts that changed, added to `message`; whether any did.
  bool add_run_parts(nlohmann::json& message);
  bool add_machine_parts(nlohmann::json& message);
  /// "travel": the machine's excursions past its travel area (as the summary counts them).
  bool add_travel_part(nlohmann::json& message);
  bool add_board_parts(nlohmann::json& message);
  bool add_device_parts(nlohmann::json& message);
  bool add_console_part(nlohmann::json& message);
  std::string make_update(bool always);
  std::string apply_input(const nlohmann::json& message);
  std::string apply_console(const nlohmann::json& message);
  std::string apply_run(const nlohmann::json& message);
  void update_motor_rates(double dt_s);
  nlohmann::json board_state_json(const std::string& name) const;
  /// Adds `value` under `key` to the array `message[field]` if it changed since last sent.
  bool add_if_changed(nlohmann::json& message, const char* field, const std::string& key, nlohmann::json value);

  Simulation& simulation_;
  RunControl& control_;
  StrokeStream strokes_;
  std::vector<MotorState> motors_;
  std::map<std::string, std::string> console_;  ///< board → text since the last update
  std::map<std::string, uint64_t> console_dropped_;
  std::optional<double> last_update_wall_s_;
  SimTime last_update_sim_ = 0;
  SentState sent_;
  uint64_t held_back_ = 0;
  uint64_t updates_made_ = 0;
  bool run_ended_ = false;
};

}  // namespace stepdance::sim::view
