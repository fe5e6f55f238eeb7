// The run's recorders: the VCD (every output port it records, and the cabled input ports through
// their cables' taps) and the CSV sampler with its columns.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "assembly/board_set.hpp"
#include "assembly/cable_link.hpp"
#include "assembly/csv_sampler.hpp"
#include "assembly/device_set.hpp"
#include "assembly/vcd_recorder.hpp"
#include "models/machine.hpp"
#include "scenario/scenario.hpp"

namespace stepdance::sim {

/// Owns the VCD recorder and the CSV sampler of one run (either may be absent). Context: host;
/// build_*() before the run, flush() between its slices, close() at its end. Writer errors throw
/// std::runtime_error("path: …").
class Recorders {
 public:
  explicit Recorders(Scheduler& scheduler) : scheduler_(scheduler) {}

  /// Opens the VCD at `path` ("" = none) recording `ports` up to `end_ns`: output ports listen
  /// to their boards' wires; input ports wait for their cables' taps (input_tap()).
  void build_vcd(const std::string& path, const std::vector<scenario::PortLineRef>& ports, SimTime end_ns,
                 BoardSet& boards);
  /// What records the lines of `board`'s input port `port` ('A'–'D') as its cable delivers
  /// them, or an empty function when the VCD does not record that port.
  CableLink::Tap input_tap(const std::string& board, char port) const;
  /// Opens the CSV at `path` ("" = none), a row every `interval_ms`: the pen (with a machine),
  /// every socket's model, then each device's own columns.
  void build_csv(const std::string& path, double interval_ms, const Machine* machine, const BoardSet& boards,
                 const DeviceSet& devices);

  /// Writes the VCD's edges before `now_ns`.
  void flush(SimTime now_ns) {
    if (vcd_) vcd_->flush(now_ns);
  }
  /// The run now ends at `end_ns`: the VCD records nothing later.
  void set_end_time(SimTime end_ns) {
    if (vcd_) vcd_->set_end_time(end_ns);
  }
  /// Closes the VCD at `end_ns`, then the CSV; appends the paths of those written to `files`.
  void close(SimTime end_ns, std::vector<std::string>& files);
  /// Stops the CSV sampler's timer (before the boards and models it reads go).
  void stop_csv() { csv_.reset(); }

 private:
  Scheduler& scheduler_;
  std::string vcd_path_;
  std::string csv_path_;
  std::unique_ptr<VcdRecorder> vcd_;
  std::map<std::string, size_t> vcd_inputs_;  ///< "board:IN_A" → recorder input
  std::unique_ptr<CsvSampler> csv_;
};

}  // namespace stepdance::sim
