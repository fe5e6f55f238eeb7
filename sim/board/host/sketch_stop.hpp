// Why a sketch was stopped before its run ended, as the simulator reports it.
#pragma once

#include <string>
#include <vector>

#include "board/host/board_source.hpp"
#include "board/host/entry_monitor.hpp"
#include "common/sim_time.hpp"

namespace stepdance::sim {

/// A sketch the simulator had to stop: it crashed, ended the program, hung or was interrupted.
/// The run ends there; a crash, an end or a hang fails it.
struct SketchStop {
  EscapeCause cause = EscapeCause::kNone;
  std::string board;
  SketchEntry entry = SketchEntry::kLoop;
  SimTime time_ns = 0;
  /// What happened: "SIGSEGV (invalid memory access)", "exit(0)", "abort()", …
  std::string what;
  /// The sketch's stack where it stopped, innermost first ("function (file+0xoffset)"); empty
  /// when not known.
  std::vector<std::string> backtrace;

  /// One line: "board 'driver': SIGSEGV (invalid memory access) in loop() at t = 1.234 s".
  std::string message() const;
};

/// Builds the report of an escape from `record`, made in `entry` of `board` at `time_ns`.
/// `source` names the backtrace's addresses in `library`, the board's own code (null: none named).
SketchStop describe_stop(const EscapeRecord& record, const std::string& board, SketchEntry entry, SimTime time_ns,
                         const BoardLibrary* library, const BoardSource* source);

}  // namespace stepdance::sim
