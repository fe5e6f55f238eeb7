// What an [[expect]] check reads of a run at its end. The assembly's Simulation answers
// (assembly/expectations.cpp), so the expectation kinds need nothing of the assembly.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/sim_time.hpp"
#include "scenario/scenario.hpp"

namespace stepdance::sim {

class Machine;
class SimDevice;
class StepperDriver;
struct PulseCounts;

/// One line of a host client's transcript.
struct HostLine {
  SimTime time = 0;
  bool from_host = true;  ///< true: the host sent it; false: the board printed it
  std::string text;       ///< without its line ending; control bytes escaped as \xNN
  bool cut = false;       ///< the line went on past 1,000 bytes: the next entry continues it
};

/// A host client at the end of the run.
struct HostOutcome {
  const std::vector<HostLine>* transcript = nullptr;
  bool completed = false;  ///< every step ran
  std::string failure;     ///< why it stopped early ("" while running or when completed)
};

/// The I2C wire time of a board's loop passes.
struct I2cLoopTiming {
  SimTime max_loop_pass_ns = 0;  ///< the most any one loop pass spent in I2C transfers
  uint64_t transfers = 0;
};

/// A finished run, as the checks see it. Context: host, after the run; every answer is null (or
/// empty) for a name the run does not have.
class FinishedRun {
 public:
  virtual ~FinishedRun() = default;
  virtual const scenario::Scenario& scenario() const = 0;
  /// The stepper / servo model in `board`'s socket `port` ('A'..'D').
  virtual const StepperDriver* stepper(const std::string& board, char port) const = 0;
  virtual const Machine* machine() const = 0;
  virtual const SimDevice* device(const std::string& name) const = 0;
  /// The pulses an output port put on its wire, or an input port decoded.
  virtual const PulseCounts* pulses(const scenario::PortLineRef& port) const = 0;
  virtual std::optional<I2cLoopTiming> i2c_timing(const std::string& board) const = 0;
  /// The host client on `board`'s USB serial.
  virtual std::optional<HostOutcome> host(const std::string& board) const = 0;
};

}  // namespace stepdance::sim
