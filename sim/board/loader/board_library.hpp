// A board shared object loaded with its own private copy of every global (one per simulated board).
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "board/abi/board_abi.h"

namespace stepdance::sim {

/// Address ranges [begin, end) of mapped machine code; at most kMax of them (a shared object
/// has one or two executable segments).
struct CodeRanges {
  static constexpr int kMax = 4;
  uintptr_t begin[kMax] = {};
  uintptr_t end[kMax] = {};
  int count = 0;
  /// Whether `address` lies in one of them. Async-signal-safe.
  bool contains(uintptr_t address) const {
    for (int i = 0; i < count; ++i) {
      if (address >= begin[i] && address < end[i]) return true;
    }
    return false;
  }
};

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
  /// Where the library's machine code is mapped (its executable segments), to tell whether an
  /// interrupted instruction is the sketch's own.
  const CodeRanges& code() const { return code_; }
  /// The file it was loaded from (a board's private copy is the same bytes), and the address its
  /// offsets count from: a backtrace's address minus load_base() is an offset in path().
  const std::string& path() const { return key_; }
  uintptr_t load_base() const { return load_base_; }

 private:
  BoardLibrary(void* handle, StepdanceBoardAttachFn attach_fn, std::string key);

  void* handle_;
  StepdanceBoardAttachFn attach_;
  std::string key_;
  uintptr_t load_base_ = 0;
  CodeRanges code_;
};

}  // namespace stepdance::sim
