// A program that runs on a simulated board by its own clock: a firmware image on an emulated chip.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "board/abi/board_abi.h"
#include "board/host/sketch_stop.hpp"
#include "board/host/wire.hpp"
#include "common/sim_time.hpp"
#include "stepdance/boards/board_definition.hpp"

namespace stepdance::sim {

class Scheduler;
class SimBoard;

/// What a SimBoard runs when its program is not a host-compiled sketch. A host-compiled sketch is
/// entered by the board (its timers call the frame ISR, its loop event calls loop()); a firmware
/// runs by itself and reaches the board's world (pins, ports, console, I2C) through the SimBoard's
/// public "program side" methods, at its own time (now_ns()).
///
/// All calls run on the simulator's thread.
class BoardFirmware {
 public:
  virtual ~BoardFirmware() = default;
  /// Binds the firmware to its board (called once, from SimBoard::attach()). False with `error`
  /// if it cannot run there.
  virtual bool start(SimBoard& board, std::string& error) = 0;
  /// Powers the board up at `time_ns`: the firmware schedules its own execution from then on.
  virtual void power_on(SimTime time_ns) = 0;
  /// The firmware's time (ns): inside its own execution, the time of the instruction running;
  /// otherwise the scheduler's.
  virtual SimTime now_ns() const = 0;
  /// A STEP pulse reached input port `port` (called at pulse.fall_ns).
  virtual void pulse_arrived(uint8_t port, const ArrivingPulse& pulse) = 0;
  /// The board's counters as the board ABI reports them (frames, faults, load).
  virtual StepdanceBoardStatsV1 stats() const = 0;
  /// Whether the firmware has set input port `port` up to receive, as a sketch's InputPort
  /// begin() does (for the summary's ports). Context: between the firmware's runs.
  virtual bool input_port_begun(uint8_t port) const { return port < 4; }
  /// How the firmware ran, for the summary's "firmware" object: named numbers (instructions
  /// retired, the frame interrupt's cost, …) in a fixed order.
  virtual std::vector<std::pair<std::string, double>> figures() const { return {}; }
  /// Calls `emit` once per named counter of the firmware's blocks, and once per kind of warning
  /// its fault path tallied, as a host-compiled board's read_counters and read_warnings do (none
  /// if the firmware cannot say). Context: between the firmware's runs.
  virtual void read_counters(StepdanceCounterFnV1 emit, void* context) { (void)emit, (void)context; }
  virtual void read_warnings(StepdanceWarningFnV1 emit, void* context) { (void)emit, (void)context; }
  /// The image file the firmware came from.
  virtual const std::string& image_path() const = 0;
  /// Calls `listener` when the firmware stops for good (a fault, no progress).
  virtual void on_stop(std::function<void(const SketchStop&)> listener) = 0;
};

/// Loads firmware images for boards: the image board (sim/image, native builds only) is plugged
/// in by the front end, as BoardSource is, so the simulator library itself needs no emulator.
class FirmwareSource {
 public:
  virtual ~FirmwareSource() = default;
  /// The firmware of the ELF at `image_path` for a board on `module`, or null with `error` (a
  /// missing or malformed image, one built for another chip). Context: loop, before the run.
  virtual std::unique_ptr<BoardFirmware> load(const std::string& image_path, const BoardDefinition& module,
                                              Scheduler& scheduler, std::string& error) const = 0;
};

}  // namespace stepdance::sim
