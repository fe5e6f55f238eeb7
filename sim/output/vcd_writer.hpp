// Streams digital line edges to a Value Change Dump file (GTKWave, PulseView, sigrok-cli).
#pragma once

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "common/edges.hpp"
#include "common/sim_time.hpp"

namespace stepdance::sim {

/// Settings of a VcdWriter.
struct VcdWriterOptions {
  /// Time unit of the file in ns: 1, 10, 100 or 1000. Edge times are rounded to it (half up).
  /// sigrok and PulseView sample the whole trace at 1/unit, so long traces want a coarser unit.
  SimTime timescale_ns = 1;
  /// Text of the `$version` header; empty writes none.
  std::string version = "Stepdance simulator";
};

/// Writes a VCD file: wires are declared first, then edges are recorded and streamed out.
///
/// Output is byte-identical for the same calls: no `$date`; scopes appear in the order their
/// first wire was declared (top-level wires last), wires in declaration order; identifiers are
/// "!", "\"", … in header order; within one timestamp, changes are ordered by wire declaration,
/// then by call order. The value section starts with `#0` and a `$dumpvars` block holding each
/// wire's level at time 0: its initial level, changed by any edge recorded at a time that rounds
/// to 0. Records that do not change a wire's level are dropped.
///
/// Memory stays bounded on long runs: edges are buffered until the caller advances the watermark
/// with flush_before(t), which writes every buffered edge older than t in time order. Edges may be
/// recorded in any order as long as none is older than the last watermark.
///
/// Errors throw: std::invalid_argument for bad names or options, std::logic_error for calls in
/// the wrong state (a wire added after output started, an edge older than the watermark),
/// std::runtime_error for I/O failures (message starts with the path).
class VcdWriter {
 public:
  /// Index of a declared wire.
  using WireId = uint32_t;

  /// Writes to the file at `path` (created or truncated).
  explicit VcdWriter(const std::string& path, VcdWriterOptions options = {});
  /// Writes to `out`, which must outlive the writer. `name` labels error messages.
  VcdWriter(std::ostream& out, std::string name, VcdWriterOptions options = {});
  /// Closes the file if close() was not called (errors are swallowed here; call close() to see them).
  ~VcdWriter();

  VcdWriter(const VcdWriter&) = delete;
  VcdWriter& operator=(const VcdWriter&) = delete;

  /// Declares a 1-bit wire `name` in module scope `scope` (e.g. "driver", "OUT_A_STEP") with its
  /// level before any edge. Names must be non-empty, printable ASCII and hold no whitespace; a
  /// scope may be empty (top level). Only before the header is written, which happens when the
  /// first edge after time 0 is written or at close().
  WireId add_wire(const std::string& scope, const std::string& name, bool initial = false);

  /// Records that `wire` changes to `level` at `time` (ns ≥ the last watermark, ≥ 0).
  void record(WireId wire, SimTime time, bool level);

  /// Records a whole edge list of one wire.
  void record_all(WireId wire, const EdgeList& edges);

  /// Writes every buffered edge with time < watermark (ns) and forbids older records from now on.
  /// The first call also writes the header. Watermarks never move back (smaller values are ignored).
  void flush_before(SimTime watermark);

  /// Writes the remaining edges and a final `#end_time` (if later than the last change) so
  /// viewers show the whole run, then flushes the stream. Idempotent.
  void close(SimTime end_time);

  /// Number of edges buffered and not yet written.
  size_t buffered_edges() const { return buffer_.size(); }

  /// The VCD identifier code of the n-th declared wire ("!" for 0, "~" for 93, "!\"" for 94, …).
  static std::string identifier(WireId index);

 private:
  struct Wire {
    std::string scope;
    std::string name;
    std::string id;
    bool level = false;
  };
  struct Pending {
    SimTime time;  // in file units
    WireId wire;
    bool level;
  };

  void write_header();
  void write_pending(SimTime before_units);
  void write_time(SimTime units);
  void check_stream();
  SimTime to_units(SimTime time_ns) const;

  std::unique_ptr<std::ofstream> file_;
  std::ostream* out_;
  std::string name_;
  VcdWriterOptions options_;
  std::vector<Wire> wires_;
  std::vector<Pending> buffer_;
  std::string chunk_;
  bool header_written_ = false;
  bool closed_ = false;
  SimTime watermark_ns_ = 0;
  SimTime last_time_units_ = 0;
};

}  // namespace stepdance::sim
