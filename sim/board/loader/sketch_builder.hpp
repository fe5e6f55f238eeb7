// Compiles a sketch (.ino) into a board shared object, cached by a hash of everything that shapes
// it: the compiling BoardSource, linked by the command line and the tests (it runs the compiler).
#pragma once

#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "board/host/board_source.hpp"
#include "board/loader/sketch_sources.hpp"

namespace stepdance::sim {

/// Builds sketches the way the Arduino IDE would, but for the host: the sketch folder's .ino
/// files are concatenated in IDE order with prototypes generated (sketch_sources.hpp), compiled
/// as C++ with Arduino.h included, together with the folder's .cpp and .c files, by the
/// compilers and flags that built the simulator, and linked with the board runtime (core +
/// simulator HAL backend + host Arduino API) into a shared object that exports only
/// stepdance_board_attach. Compiler messages name the sketch's own files and lines.
///
/// The result is cached under cache_dir in two steps. The sources key hashes every file of the
/// sketch folder (.ino, .cpp, .c and headers), the compilers, their flags and the runtime
/// library's contents; <sources key>.deps then lists every file the compiler read the last time
/// (its dependency output, so a header included from outside the folder, `../shared/val.h`, or
/// by another name, `table.inc`, counts too), and the library is <sources key>-<hash of those
/// files' contents>.so. An edited sketch, an edited header wherever it lies, or a rebuilt
/// runtime therefore gets a fresh build, and an unchanged one is loaded without compiling.
/// Concurrent builders are safe: each writes temporary files and renames them into place.
class SketchBuilder : public BoardSource {
 public:
  /// `cache_dir` is created on first use. Empty means default_cache_dir().
  explicit SketchBuilder(std::string cache_dir = {});

  /// Builds (or finds in the cache) the board library for `sketch_path` (an .ino or a sketch
  /// folder). A sketch built before by this builder is not looked up again: the boards of one run
  /// that share a sketch cost one lookup (hashing the ~470 files a build read took ~50 ms a
  /// board). Context: loop (runs the compiler); any thread.
  SketchBuild build(const std::string& sketch_path) const override;
  /// Names the offsets with one run of addr2line (binutils, which the compiler needs anyway).
  std::vector<std::string> symbols(const std::string& library_path,
                                   const std::vector<uintptr_t>& offsets) const override;

  /// $STEPDANCE_SKETCH_CACHE, else $XDG_CACHE_HOME/stepdance/sketches, else
  /// $HOME/.cache/stepdance/sketches, else the build tree's sketch-cache/.
  static std::string default_cache_dir();
  /// The files and folders a build reads besides the sketch and the system's: the include
  /// folders, the runtime library and the export map (a confined build may read only these).
  static std::vector<std::string> toolchain_paths();
  const std::string& cache_dir() const { return cache_dir_; }

 private:
  std::string cache_key(const SketchSources& sources) const;
  std::vector<std::string> c_command(const std::string& source, const std::string& object) const;
  std::vector<std::string> link_command(const std::vector<std::string>& objects, const std::string& output) const;
  std::vector<std::string> cxx_command(const SketchSources& sources, const std::string& source,
                                       const std::string& object) const;
  // Writes <stem>.ino.cpp, compiles each source (with its dependency file) and links them into
  // <stem>.so; lists its temporary files in scratch and every file the compiler read in inputs.
  bool compile(const SketchSources& sources, const std::string& stem, std::vector<std::string>& scratch,
               SketchBuild& result) const;
  // The library of a previous build whose recorded inputs are all unchanged, if any.
  bool find_cached(const std::string& sources_key, SketchBuild& result) const;
  // Records the inputs and moves <stem>.so to its place; false with result.error if it cannot.
  bool store(const std::string& sources_key, const std::string& stem, SketchBuild& result) const;

  // The uncached build().
  SketchBuild build_once(const std::string& sketch_path) const;

  std::string cache_dir_;
  mutable std::mutex built_mutex_;
  mutable std::map<std::string, SketchBuild> built_;  ///< sketch path → its successful build
};

}  // namespace stepdance::sim
