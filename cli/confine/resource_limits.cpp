// set_resource_limits and drop_privileges: what a confined process may use, and no way back.
#include <linux/capability.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>

#include "confinement.hpp"

namespace stepdance::cli::confine {
namespace {

/// After the soft CPU limit's SIGXCPU, the hard one's SIGKILL this much later.
constexpr rlim_t kCpuGraceS = 5;

std::string limit(int resource, rlim_t soft, rlim_t hard, const char* name) {
  const rlimit value{soft, hard};
  if (setrlimit(resource, &value) == 0) return "";
  return std::string("cannot limit ") + name + ": " + std::strerror(errno);
}

bool under_address_sanitizer() {
#if defined(__SANITIZE_ADDRESS__)
  return true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  return true;
#endif
#endif
  return false;
}

}  // namespace

std::string set_resource_limits(const ConfinementLimits& limits) {
  const auto cpu = static_cast<rlim_t>(std::ceil(limits.cpu_s));
  std::string problem = limit(RLIMIT_CPU, cpu, cpu + kCpuGraceS, "CPU time");
  if (problem.empty()) problem = limit(RLIMIT_FSIZE, limits.file_bytes, limits.file_bytes, "file size");
  if (problem.empty()) problem = limit(RLIMIT_NOFILE, limits.open_files, limits.open_files, "open files");
  if (problem.empty()) problem = limit(RLIMIT_CORE, 0, 0, "core files");
  // AddressSanitizer reserves terabytes of address space for its shadow: no limit there.
  if (problem.empty() && !under_address_sanitizer()) {
    problem = limit(RLIMIT_AS, limits.memory_bytes, limits.memory_bytes, "memory");
  }
  return problem;
}

std::string drop_privileges() {
  // Every capability out of the bounding set (a root process would get them back at exec), then
  // out of the process's own sets.
  for (int capability = 0; capability <= 63; ++capability) {
    if (prctl(PR_CAPBSET_DROP, capability, 0, 0, 0) != 0 && errno != EINVAL && errno != EPERM) {
      return std::string("cannot drop a capability: ") + std::strerror(errno);
    }
  }
  __user_cap_header_struct header{_LINUX_CAPABILITY_VERSION_3, 0};
  __user_cap_data_struct none[2] = {};
  if (syscall(SYS_capset, &header, none) != 0) return std::string("cannot drop capabilities: ") + std::strerror(errno);
  if (prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) != 0)
    return std::string("cannot set no_new_privs: ") + std::strerror(errno);
  return "";
}

}  // namespace stepdance::cli::confine
