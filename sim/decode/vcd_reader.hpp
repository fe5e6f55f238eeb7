// Reads VCD files (ours, GTKWave's, PulseView/sigrok exports) into per-wire edge lists in ns.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "common/edges.hpp"
#include "common/sim_time.hpp"

namespace stepdance::sim {

/// One `$var` of a VCD file.
struct VcdWire {
  std::string scope;  ///< enclosing scopes joined with '.', empty at top level
  std::string name;   ///< reference name, with a bit index appended when given ("data[3]")
  std::string id;     ///< identifier code
  int width = 1;      ///< bits; only 1-bit wires get edges
  /// Level at the file's first timestamp (usually #0): the last value assigned there, low when
  /// none was. `x` and `z` read as low.
  bool initial = false;
  /// Level changes after the first timestamp, times in ns, each one changing the level.
  EdgeList edges;

  /// "scope.name", or just the name at top level.
  std::string full_name() const { return scope.empty() ? name : scope + "." + name; }
};

/// The contents of a VCD file.
struct VcdCapture {
  std::vector<VcdWire> wires;  ///< in declaration order
  SimTime timescale_fs = 1'000'000;  ///< the file's time unit in femtoseconds
  SimTime start_time = 0;  ///< first timestamp in ns
  SimTime end_time = 0;    ///< last timestamp in ns
};

/// The result of reading a VCD: the capture, or an error.
struct VcdReadResult {
  bool ok = false;
  /// "file:line: message" when !ok (line 0 when the file cannot be opened).
  std::string error;
  /// The file ends mid-stream (its last line has no newline, or a dump block no $end): the
  /// capture holds everything before the cut and `warning` says where it is.
  bool truncated = false;
  std::string warning;
  VcdCapture capture;
};

/// Reads the VCD file at `path`. Never throws for bad content: truncated or garbage input gives
/// an error. Accepted: any `$timescale` of 1/10/100 s…fs (times rounded to the nearest ns),
/// nested scopes, several vars sharing one identifier, multi-character identifiers, `$dumpvars`
/// / `$dumpall` / `$dumpon` / `$dumpoff` blocks, `x`/`z` values (read as low), `b`/`r` vector
/// and real values (checked, ignored), `$comment`, `$date`, `$version` and unknown
/// declaration commands, value changes before the first timestamp (taken as time 0), and the
/// "META samplerate: N" lines sigrok-cli writes before the header when it converts a file.
/// Rejected with an error: time going backwards, undeclared identifiers, malformed commands,
/// a missing `$enddefinitions` or `$end` of a declaration, times that overflow 64-bit ns.
/// Read but marked truncated: a file whose last line has no newline (its last, possibly cut,
/// token is dropped) or whose value changes end inside a dump block.
VcdReadResult read_vcd_file(const std::string& path);

/// Reads VCD text from `in`; `name` is the file name used in error messages.
VcdReadResult read_vcd(std::istream& in, const std::string& name);

}  // namespace stepdance::sim
