// A board shared object loaded with its own private copy of every global (one per simulated board).
#pragma once

#include <memory>
#include <string>

#include "abi/board_abi.h"

namespace stepdance::sim {

/// One loaded board library. Each instance has its own globals: the first board that uses a
/// given .so loads it in place, and every further board loads a private copy of the file
/// (dlopen identifies libraries by path and inode, so a copy is a distinct library), which is
/// unlinked as soon as it is mapped. Loaded with RTLD_NOW | RTLD_LOCAL, so nothing the sketch
/// defines can be seen by, or interpose on, another board or the simulator.
class BoardLibrary {
 public:
  /// Loads `library_path`; on failure returns nullptr and sets `error`.
  static std::unique_ptr<BoardLibrary> load(const std::string& library_path, std::string& error);
  /// Unloads the library (running the sketch's global destructors).
  ~BoardLibrary();
  BoardLibrary(const BoardLibrary&) = delete;
  BoardLibrary& operator=(const BoardLibrary&) = delete;

  /// The library's stepdance_board_attach entry point.
  StepdanceBoardAttachFn attach() const { return attach_; }

 private:
  BoardLibrary(void* handle, StepdanceBoardAttachFn attach_fn, std::string key)
      : handle_(handle), attach_(attach_fn), key_(std::move(key)) {}

  void* handle_;
  StepdanceBoardAttachFn attach_;
  std::string key_;
};

}  // namespace stepdance::sim
