// filter_system_calls: the seccomp filter of a confined process (libseccomp).
#include <seccomp.h>

#include <cerrno>
#include <cstring>

#include "confinement.hpp"

namespace stepdance::cli::confine {
namespace {

// Refused with EPERM: sockets (no network, no local services), leaving the process group the
// server ends (setsid, setpgid), raising a limit, and io_uring (which could open sockets past
// this filter).
constexpr int kRefused[] = {SCMP_SYS(socket),           SCMP_SYS(setsid),         SCMP_SYS(setpgid),
                            SCMP_SYS(setrlimit),        SCMP_SYS(io_uring_setup), SCMP_SYS(io_uring_enter),
                            SCMP_SYS(io_uring_register)};

}  // namespace

std::string filter_system_calls() {
  scmp_filter_ctx filter = seccomp_init(SCMP_ACT_ALLOW);
  if (filter == nullptr) return "seccomp: cannot make a filter";
  int failed = 0;
  for (const int call : kRefused) failed |= seccomp_rule_add(filter, SCMP_ACT_ERRNO(EPERM), call, 0);
  // prlimit64 reads limits too (getrlimit is built on it): only setting one is refused.
  failed |= seccomp_rule_add(filter, SCMP_ACT_ERRNO(EPERM), SCMP_SYS(prlimit64), 1, SCMP_A2(SCMP_CMP_NE, 0));
  if (failed == 0) failed = seccomp_load(filter);
  seccomp_release(filter);
  return failed == 0 ? "" : std::string("seccomp: cannot load the filter: ") + std::strerror(-failed);
}

}  // namespace stepdance::cli::confine
