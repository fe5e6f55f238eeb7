// confine_process and missing_guards: the guards in order, and what this kernel offers.
#include "confinement.hpp"

#include <linux/seccomp.h>
#include <sys/prctl.h>

#include <cerrno>

namespace stepdance::cli::confine {

std::vector<std::string> missing_guards() {
  std::vector<std::string> missing;
  const int abi = landlock_abi();
  if (abi < 6) {
    missing.push_back("Landlock ABI " + std::to_string(abi) +
                      " (6 is needed, Linux 6.12 or later with landlock in its LSMs): files and signals unguarded");
  }
  // PR_GET_SECCOMP fails with EINVAL on a kernel built without seccomp.
  if (prctl(PR_GET_SECCOMP, 0, 0, 0, 0) < 0 && errno == EINVAL) missing.push_back("seccomp: sockets unguarded");
  return missing;
}

std::string confine_process(const ConfinementPaths& paths, const ConfinementLimits& limits) {
  std::string problem = set_resource_limits(limits);
  if (problem.empty()) problem = drop_privileges();
  if (problem.empty()) problem = restrict_file_system(paths);
  if (problem.empty()) problem = filter_system_calls();
  return problem;
}

}  // namespace stepdance::cli::confine
