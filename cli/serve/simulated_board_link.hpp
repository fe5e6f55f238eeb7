// A board of a live simulation run by `stepdance serve <scenario>`'s child process
// (serve/board_runner.hpp), paced by its event loop's timer.
#pragma once

#include <chrono>
#include <functional>
#include <string>

#include <boost/asio/io_context.hpp>
#include <boost/asio/steady_timer.hpp>
#include <nlohmann/json.hpp>

#include "assembly/simulation.hpp"
#include "board_link.hpp"

namespace stepdance::cli::serve {

/// Runs `simulation` in the event loop: every tick it catches up with the wall clock (times
/// `speed`) in steps of one simulated millisecond, handing the board's console lines to on_line()
/// and the bytes send() queued to the board between steps (the USB serial a pty would carry, but
/// without the pty). Every kDrawingPeriod it reports the machine's pen and the new parts of its
/// strokes to on_drawing() (see drawing_update()). Context: the event loop.
class SimulatedBoardLink : public BoardLink {
 public:
  static constexpr std::chrono::milliseconds kTickPeriod{2};
  static constexpr std::chrono::milliseconds kDrawingPeriod{50};
  /// Points of the drawing sent at most per update; the rest follow in the next ones.
  static constexpr size_t kMaxPointsPerUpdate = 4000;

  SimulatedBoardLink(boost::asio::io_context& io, sim::Simulation& simulation, const std::string& board, double speed);
  void send(const std::string& bytes) override;
  std::string describe() const override { return "simulated board " + board_name_; }
  /// Receives each drawing update (a JSON object, see drawing_update()).
  void on_drawing(std::function<void(const nlohmann::json&)> handler) { on_drawing_ = std::move(handler); }
  /// The machine's travel area and the run's state as JSON, for a page that just connected.
  nlohmann::json machine_description() const;
  /// Stops ticking (the run is over). The simulation may then be finished.
  void stop();

  /// {"drawing": {"pen": [x, y], "down": bool, "t": simulated s, "strokes": [{"index": i,
  /// "from": k, "points": [[x, y], …]}, …]}}: stroke i from point k on (k re-sends the last
  /// point sent, which the simulator may still have moved). Empty strokes when nothing changed.
  nlohmann::json drawing_update();

 private:
  void schedule();
  void tick();

  boost::asio::steady_timer timer_;
  sim::Simulation& simulation_;
  sim::SimBoard* board_;
  std::string board_name_;
  double speed_;
  std::string to_board_;
  LineSplitter lines_{1 << 16};
  std::chrono::steady_clock::time_point wall_start_;
  std::chrono::steady_clock::time_point next_drawing_;
  sim::SimTime sim_start_ = 0;
  size_t strokes_sent_ = 0;  ///< strokes complete on the page (all points sent)
  size_t points_sent_ = 0;   ///< points sent of stroke strokes_sent_
  std::function<void(const nlohmann::json&)> on_drawing_;
  bool stopped_ = false;
};

}  // namespace stepdance::cli::serve
