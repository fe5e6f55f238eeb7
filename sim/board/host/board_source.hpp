// Where a simulation gets each board's library: compiled from its sketch (the command line, the
// tests) or precompiled (a build without a compiler, such as the WebAssembly page).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace stepdance::sim {

/// The outcome of building one sketch.
struct SketchBuild {
  bool ok = false;
  std::string library_path;  ///< the board .so, when ok
  bool from_cache = false;   ///< true if no compiler ran
  std::string error;         ///< when !ok: what failed, with the compiler's own messages
  std::string diagnostics;   ///< when ok and freshly compiled: the compiler's warnings, if any
  /// When ok: every file the compiler read (its -MD dependency output: the sketch's sources and
  /// every header they include, wherever it lies, system headers too), absolute, sorted.
  std::vector<std::string> inputs;
};

/// Gives the simulation a board library for each sketch. The simulator library holds no
/// compiler: SketchBuilder (board/loader/sketch_builder.hpp, linked by the command line and the
/// tests) is the one that compiles.
class BoardSource {
 public:
  virtual ~BoardSource() = default;
  /// The board library for the sketch at `sketch_path` (an .ino or a sketch folder).
  /// Context: loop (may run a compiler; not from a board's entry).
  virtual SketchBuild build(const std::string& sketch_path) const = 0;
  /// One name per offset into the code of the library at `library_path` ("function at
  /// file:line"), "" where it cannot say. Context: loop, after a sketch stopped. This default
  /// knows none.
  virtual std::vector<std::string> symbols(const std::string& library_path,
                                           const std::vector<uintptr_t>& offsets) const {
    (void)library_path;
    return std::vector<std::string>(offsets.size());
  }
};

}  // namespace stepdance::sim
