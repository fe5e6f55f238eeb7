// PrecompiledBoards: the WebAssembly build's BoardSource, a side module per sketch folder.
#pragma once

#include <map>
#include <string>

#include "board/host/board_source.hpp"

namespace stepdance::web {

/// Hands the simulation the board library precompiled for each sketch (scripts/build-web.sh
/// builds one side module per example folder). A sketch is looked up by its folder's name, so
/// "…/StepASketch/StepASketch.ino" and "…/StepASketch" find the same board; a sketch with no
/// board registered is refused with a message that names the known ones (the page cannot
/// compile). Each call hands out a new copy of the module, so every board of every run starts
/// from fresh globals (the memory of a finished run's boards is not given back: WebAssembly
/// cannot unload a module). Context: loop.
class PrecompiledBoards : public sim::BoardSource {
 public:
  /// Registers the board library at `library_path` (in the module's file system) for sketch
  /// folders named `folder_name`; a second call for the same name replaces the first.
  void add(const std::string& folder_name, const std::string& library_path);
  sim::SketchBuild build(const std::string& sketch_path) const override;

 private:
  std::map<std::string, std::string> libraries_;  ///< folder name → library path
  mutable unsigned copies_ = 0;                   ///< copies handed out so far (for unique names)
};

/// The name of the folder a sketch lives in: the path's last part for a folder, its parent's
/// for an .ino file ("a/b/StepASketch/StepASketch.ino" → "StepASketch").
std::string sketch_folder_name(const std::string& sketch_path);

}  // namespace stepdance::web
