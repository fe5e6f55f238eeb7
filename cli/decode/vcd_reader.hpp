// Reads VCD files (ours, GTKWave's, PulseView/sigrok exports) into per-wire edge lists in ns.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <memory>
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
  std::vector<VcdWire> wires;        ///< in declaration order
  SimTime timescale_fs = 1'000'000;  ///< the file's time unit in femtoseconds
  SimTime start_time = 0;            ///< first timestamp in ns
  SimTime end_time = 0;              ///< last timestamp in ns
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

/// Told of a capture's value changes as VcdStreamReader reads them.
class VcdValueListener {
 public:
  /// The level of 1-bit wire `wire` when the file's first timestamp is over (the last value
  /// assigned at or before it, low when none was): once per 1-bit wire, in declaration order,
  /// before the first on_edge (at the end, for a capture whose time never moves on).
  virtual void on_initial_level(std::size_t wire, bool high) = 0;
  /// A 1-bit wire's level changed at `time_ns`, after the first timestamp; times never go back.
  virtual void on_edge(std::size_t wire, SimTime time_ns, bool high) = 0;

 protected:
  ~VcdValueListener() = default;
};

/// Reads a VCD in two steps, the declarations and then the value changes, which go to a
/// listener as they are read and are not kept: memory stays within the declarations (bounded
/// below), a chunk of the file and one token (VcdTokenizer), whatever the file's size.
/// Context: host, one thread.
class VcdStreamReader {
 public:
  /// The most wires a capture may declare.
  static constexpr std::size_t kMaxWires = 100000;
  /// The most text the declarations may keep: scope, name and identifier bytes of every wire,
  /// and the names of the open scopes.
  static constexpr std::size_t kMaxDeclarationBytes = 4 * 1024 * 1024;

  /// `name` is the file name used in messages.
  VcdStreamReader(std::istream& in, std::string name);
  ~VcdStreamReader();
  VcdStreamReader(const VcdStreamReader&) = delete;
  VcdStreamReader& operator=(const VcdStreamReader&) = delete;

  /// Reads up to `$enddefinitions`; false when the declarations are malformed or too large
  /// (take_result() says why).
  bool read_declarations();
  /// The declared wires (their edges empty), the timescale. Valid after read_declarations().
  const VcdCapture& declarations() const;
  /// Reads the value changes to the end of the file, telling `listener`; false when they are
  /// malformed (take_result() says why). Precondition: read_declarations() returned true.
  bool read_values(VcdValueListener& listener);
  /// The outcome: ok, error, truncation, and the capture's wires (without edges), timescale and
  /// first and last timestamps. Call once, at the end.
  VcdReadResult take_result();

 private:
  class Parser;
  std::unique_ptr<Parser> parser_;
};

/// Reads the VCD file at `path`, keeping every wire's edges (for tests and small captures;
/// `stepdance decode` streams with VcdStreamReader). Never throws for bad content: truncated or
/// garbage input gives an error. Accepted: any `$timescale` of 1/10/100 s…fs (times rounded to the nearest ns),
/// nested scopes, several vars sharing one identifier, multi-character identifiers, `$dumpvars`
/// / `$dumpall` / `$dumpon` / `$dumpoff` blocks, `x`/`z` values (read as low), `b`/`r` vector
/// and real values (checked, ignored), `$comment`, `$date`, `$version` and unknown
/// declaration commands, value changes before the first timestamp (taken as time 0), and the
/// "META samplerate: N" lines sigrok-cli writes before the header when it converts a file.
/// Rejected with an error: time going backwards, undeclared identifiers, malformed commands,
/// a missing `$enddefinitions` or `$end` of a declaration, times that overflow 64-bit ns, a
/// token longer than VcdTokenizer::kMaxTokenBytes, more than VcdStreamReader::kMaxWires wires
/// or kMaxDeclarationBytes of declarations.
/// Read but marked truncated: a file whose last line has no newline (its last, possibly cut,
/// token is dropped) or whose value changes end inside a dump block.
VcdReadResult read_vcd_file(const std::string& path);

/// Reads VCD text from `in`; `name` is the file name used in error messages.
VcdReadResult read_vcd(std::istream& in, const std::string& name);

}  // namespace stepdance::sim
