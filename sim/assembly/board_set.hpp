// The boards of a simulation: each scenario board's sketch built (or its firmware image loaded),
// checked against its scenario module, and its driver sockets filled with stepper and servo models.
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "assembly/output_plan.hpp"
#include "assembly/simulation_options.hpp"
#include "board/host/sim_board.hpp"
#include "kernel/scheduler/scheduler.hpp"
#include "models/servo_board.hpp"
#include "models/stepper_driver.hpp"
#include "scenario/scenario.hpp"

namespace stepdance::sim {

/// A driver socket: the model in it (a stepper or a servo board) and what feeds it the port's
/// STEP/DIR.
struct BoardSocket {
  std::unique_ptr<StepperDriver> stepper;
  std::unique_ptr<ServoBoard> servo;
  std::unique_ptr<WireListener> feeder;
};

/// One scenario board, running, with its four sockets (A–D).
struct BoardSlot {
  const scenario::BoardConfig* config = nullptr;
  std::unique_ptr<SimBoard> board;
  std::array<BoardSocket, 4> sockets;
};

/// Owns every board of a run, in scenario order. Context: host; build() before the run, lookups
/// any time.
class BoardSet {
 public:
  /// `motion` is set true whenever a socket's model is fed a frame with pulses (the machine is
  /// re-read then); it must outlive the boards.
  BoardSet(Scheduler& scheduler, const SimulationOptions& options, bool* motion)
      : scheduler_(scheduler), options_(options), motion_(motion) {}

  /// Builds every sketch first and checks `outputs` against every file the compilers read,
  /// before any board library is loaded (loading runs the sketch's global constructors); then
  /// loads, attaches and checks each board and fills its sockets. A board's SD card folder is
  /// `storage_directory`/NAME.sd. `on_stop` hears every sketch the simulator had to stop.
  bool build(const scenario::Scenario& scenario, const std::string& storage_directory,
             const std::vector<PlannedOutput>& outputs, std::function<void(const SketchStop&)> on_stop,
             SimulationError& error);
  /// Unloads every sketch (the scheduler and the models they call must still exist).
  void clear() { slots_.clear(); }

  const std::vector<BoardSlot>& slots() const { return slots_; }
  /// The board named `name`, or null.
  SimBoard* board(const std::string& name) const;
  /// The slot of a board the scenario names (the scenario's checks made sure it exists).
  BoardSlot& slot(const std::string& name);
  const BoardSlot* find(const std::string& name) const;
  /// The stepper / servo in `board`'s socket `port` ('A'–'D'), or null.
  const StepperDriver* stepper(const std::string& board, char port) const;
  const ServoBoard* servo(const std::string& board, char port) const;

  /// Every board's run ends at `end_ns` (pulses after it are not counted as sent).
  void set_end_time(SimTime end_ns);
  /// Powers every board on at time 0 (setup(), then loop()), its run ending at `end_ns`.
  void power_on(SimTime end_ns);
  /// Hands every board's unfinished console line on (printed without a newline).
  void flush_console_lines();
  /// A failed check for each board whose sketch touched storage from an interrupt: on the board
  /// a card access can take far longer than a frame, so this fails the run whatever it expects.
  void add_storage_violations(std::vector<ExpectationResult>& results) const;

 private:
  bool build_sketches(const scenario::Scenario& scenario, std::vector<SketchBuild>& builds,
                      std::vector<bool>& runs_image, SimulationError& error) const;
  bool add_board(const scenario::Scenario& scenario, const scenario::BoardConfig& config, const SketchBuild& build,
                 const std::string& storage_directory, SimulationError& error);
  /// The firmware image `config`'s board runs ("" for its host-compiled sketch).
  std::string image_of(const scenario::BoardConfig& config) const;
  /// The board for `config`: its sketch's library (`build`) or its firmware image loaded.
  std::unique_ptr<SimBoard> make_board(const scenario::Scenario& scenario, const scenario::BoardConfig& config,
                                       const SketchBuild& build, const std::string& storage_directory,
                                       SimulationError& error) const;
  std::unique_ptr<SimBoard> load_image(const scenario::Scenario& scenario, const scenario::BoardConfig& config,
                                       const BoardOptions& board_options, SimulationError& error) const;
  void fill_sockets(BoardSlot& slot);

  Scheduler& scheduler_;
  const SimulationOptions& options_;
  bool* motion_;
  std::function<void(const SketchStop&)> on_stop_;
  std::vector<BoardSlot> slots_;
};

}  // namespace stepdance::sim
