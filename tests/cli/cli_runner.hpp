// Runs the `stepdance` command as a user does, capturing its exit status, stdout and stderr.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "sim/assembly/simulation_fixture.hpp"

namespace stepdance::sim::test {

inline const std::string kStepdance = STEPDANCE_BUILD_DIR "/stepdance";

struct CommandResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

/// Runs `stepdance <arguments>` through the shell, capturing stdout and stderr in `scratch`.
inline CommandResult stepdance(const std::string& arguments, const std::string& scratch) {
  std::filesystem::create_directories(scratch);
  const std::string out = scratch + "/stdout.txt", err = scratch + "/stderr.txt";
  const int status = std::system((kStepdance + " " + arguments + " >" + out + " 2>" + err).c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_file(out), read_file(err)};
}

}  // namespace stepdance::sim::test
