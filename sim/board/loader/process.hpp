// Runs a child process (the compiler) with its output captured, without a shell.
#pragma once

#include <string>
#include <vector>

namespace stepdance::sim {

/// What a finished child process left behind.
struct ProcessResult {
  bool started = false;  ///< false if the program could not be run at all
  int exit_code = -1;    ///< exit status, or 128 + signal number if it was killed
  std::string output;    ///< everything it wrote to stdout and stderr, interleaved
};

/// Runs argv[0] (looked up in PATH) with the given arguments and waits for it. stdout and stderr
/// go to `log_path`, which is then read back into ProcessResult::output.
ProcessResult run_process(const std::vector<std::string>& argv, const std::string& log_path);

}  // namespace stepdance::sim
