// WebRun: one scenario run in the WebAssembly build, driven in slices by a Web Worker or node.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "assembly/simulation.hpp"
#include "precompiled_boards.hpp"
#include "view/run_control.hpp"
#include "view/view_session.hpp"

namespace stepdance::web {

/// A scenario loaded from text, its boards from PrecompiledBoards, run a slice at a time
/// (run_until), seen through the view protocol's ViewSession (the same class the live command
/// line serves over WebSocket, so a page cannot tell which side it talks to), and finished into
/// the run's result (sim/assembly/run_result.hpp). No VCD and no pictures are written: the page
/// draws its own. Context: the one thread that runs the module.
class WebRun {
 public:
  /// Parses `text` as the scenario file `path` (relative paths in it resolve against its folder
  /// in the module's file system) and builds the simulation; null with `error` set
  /// (`file:line: message` lines) when the scenario or a board is wrong.
  static std::unique_ptr<WebRun> open(const std::string& path, std::string_view text,
                                      std::shared_ptr<const PrecompiledBoards> boards, std::string& error);

  /// Runs up to `end_s` of simulated time (at most the duration). Context: between messages.
  void run_until(double end_s);
  double now_s() const;
  double duration_s() const;
  /// Whether the run reached its end or was stopped (a sketch stop).
  bool done() const;
  /// Runs to the end and returns the run's result document (run_result_json); a second call
  /// returns the same text. Output failures are returned as {"error": …}.
  const std::string& finish();

  /// The view protocol, on a session made at the first call of hello().
  std::string hello();
  std::optional<std::string> update(double wall_s);
  std::string update_now();
  std::vector<std::string> receive(std::string_view text);
  /// What the page asked of the run's pace ({"paused": bool, "speed": number, 0 = max}).
  const sim::view::RunControl& control() const { return control_; }

 private:
  WebRun() = default;
  void console_line(const std::string& board, const std::string& line);

  std::unique_ptr<sim::Simulation> simulation_;
  sim::view::RunControl control_;
  std::unique_ptr<sim::view::ViewSession> session_;
  std::optional<std::string> result_;
};

}  // namespace stepdance::web
