// Compiles a sketch (.ino) into a board shared object, cached by a hash of everything that shapes it.
#pragma once

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
};

/// Builds sketches the way the Arduino IDE would, but for the host: the .ino is compiled as C++
/// with Arduino.h force-included, by the compiler and flags that built the simulator, and
/// linked with the board runtime (core + simulator HAL backend + host Arduino API) into a
/// shared object that exports only stepdance_board_attach.
///
/// The result is cached under cache_dir as <hash>.so, where the hash covers the sketch text, the
/// other sources in the sketch's folder (.h/.hpp/.ino/.cpp), the compiler, its flags and the
/// runtime library's contents. An edited sketch or a rebuilt runtime therefore gets a fresh
/// build, and an unchanged one is loaded without compiling. Concurrent builders are safe: each
/// writes a temporary file and renames it into place.
class SketchBuilder {
 public:
  /// `cache_dir` is created on first use. Empty means default_cache_dir().
  explicit SketchBuilder(std::string cache_dir = {});

  /// Builds (or finds in the cache) the board library for `sketch_path`.
  SketchBuild build(const std::string& sketch_path) const;

  /// $STEPDANCE_SKETCH_CACHE, else $XDG_CACHE_HOME/stepdance/sketches, else
  /// $HOME/.cache/stepdance/sketches, else the build tree's sketch-cache/.
  static std::string default_cache_dir();
  const std::string& cache_dir() const { return cache_dir_; }

 private:
  std::string cache_key(const std::string& sketch_path) const;
  std::vector<std::string> compile_command(const std::string& sketch_path, const std::string& output) const;

  std::string cache_dir_;
};

}  // namespace stepdance::sim
