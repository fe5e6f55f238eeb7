// Records chosen ports' STEP/DIR lines into a VCD file while the simulation runs.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "board/host/wire.hpp"
#include "common/edges.hpp"
#include "output/vcd_writer.hpp"

namespace stepdance::sim {

/// Owns the VcdWriter. Wires are named `<board>.<OUT|IN>_<letter>_STEP` / `_DIR`, so
/// `stepdance decode` pairs them by itself. Declare every port before the run starts; call
/// flush() as time passes (memory stays bounded) and close() at the end. Writer errors throw.
class VcdRecorder {
 public:
  explicit VcdRecorder(const std::string& path);
  ~VcdRecorder();

  /// Declares the lines of `board`'s output port and returns a listener that records what the
  /// port plays. The recorder owns the listener.
  WireListener* record_output(const std::string& board, char port_letter);
  /// Declares the lines of `board`'s input port; returns the index to pass to record_input().
  size_t declare_input(const std::string& board, char port_letter);
  /// Records edges arriving at a declared input port.
  void record_input(size_t input, const PortWaveform& waveform);

  /// The run ends at `end_ns`: later edges are not recorded (a pulse still high then shows as cut).
  void set_end_time(SimTime end_ns) { end_ns_ = end_ns; }
  /// Writes every edge before `now_ns` (no later edge can be older than the current time).
  void flush(SimTime now_ns) { writer_.flush_before(now_ns); }
  /// Writes the rest and ends the file at `end_ns`.
  void close(SimTime end_ns) { writer_.close(end_ns); }

 private:
  class OutputTap;
  struct LinePair {
    VcdWriter::WireId step;
    VcdWriter::WireId dir;
  };
  LinePair declare(const std::string& board, const std::string& prefix);
  void record(const LinePair& lines, const PortWaveform& waveform);

  VcdWriter writer_;
  std::vector<std::unique_ptr<OutputTap>> outputs_;
  std::vector<LinePair> inputs_;
  SimTime end_ns_ = INT64_MAX;
};

}  // namespace stepdance::sim
