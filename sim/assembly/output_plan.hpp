// What a run will write and what it reads, checked against each other before anything runs:
// outputs never replace an input and never collide with one another.
#pragma once

#include <string>
#include <vector>

namespace stepdance::sim {

/// Who asked for an output: a scenario line or a command-line option.
struct OutputOrigin {
  /// Where to report a problem: "file:line", "--csv", or the scenario file for a default name.
  std::string where;
  /// What it is, for messages: "'svg'", "--csv", "the SD card folder of board 'driver'".
  std::string what;
  /// A name nobody wrote (an [output] key left at its default): a clash with it is reported
  /// where the other output was asked for, when that was written.
  bool defaulted = false;
};

/// One file or folder a run writes.
struct PlannedOutput {
  std::string path;  ///< absolute
  OutputOrigin origin;
  bool folder = false;  ///< a folder the run owns as a whole (a board's SD card)
};

/// One file a run reads: the scenario, a sketch's sources and every file its compiler read,
/// the files a timeline or host client sends.
struct RunInput {
  std::string path;  ///< absolute
  std::string what;  ///< for messages: "the scenario", "a source of board 'driver''s sketch"
};

/// Every conflict, each as "where: message", in the order of `outputs`:
///  - an output that is an input (the same path after resolving symlinks, or the same file by
///    device and inode) or inside an output folder that holds an input;
///  - two outputs with the same path, or one inside the other (a file inside a board's SD
///    card folder, a file where another output needs a folder).
/// Empty when the run may go ahead. Context: host, before a run (reads file metadata only).
std::vector<std::string> output_conflicts(const std::vector<PlannedOutput>& outputs,
                                          const std::vector<RunInput>& inputs);

/// The conflicts, one a line, as a refusal prints them; empty when there are none.
std::string output_conflicts_text(const std::vector<PlannedOutput>& outputs, const std::vector<RunInput>& inputs);

}  // namespace stepdance::sim
