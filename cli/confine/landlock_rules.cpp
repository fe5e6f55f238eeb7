// restrict_file_system: a Landlock ruleset for the run's paths, with signals scoped to it.
#include <fcntl.h>
#include <linux/landlock.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "confinement.hpp"

namespace stepdance::cli::confine {
namespace {

// Debian 12's kernel headers stop at Landlock ABI 2; the later fields and rights are the
// kernel's own (include/uapi/linux/landlock.h of Linux 6.12).
struct RulesetAttr {
  uint64_t handled_access_fs;
  uint64_t handled_access_net;
  uint64_t scoped;
};
constexpr uint64_t kTruncate = 1ull << 14;          // ABI 3
constexpr uint64_t kIoctlDev = 1ull << 15;          // ABI 5
constexpr uint64_t kScopeAbstractUnix = 1ull << 0;  // ABI 6
constexpr uint64_t kScopeSignal = 1ull << 1;        // ABI 6
constexpr int kNeededAbi = 6;

constexpr uint64_t kReadRights =
    LANDLOCK_ACCESS_FS_EXECUTE | LANDLOCK_ACCESS_FS_READ_FILE | LANDLOCK_ACCESS_FS_READ_DIR;
constexpr uint64_t kFileRights =
    LANDLOCK_ACCESS_FS_EXECUTE | LANDLOCK_ACCESS_FS_WRITE_FILE | LANDLOCK_ACCESS_FS_READ_FILE | kTruncate | kIoctlDev;
constexpr uint64_t kAllRights = (1ull << 16) - 1;

int create_ruleset(const RulesetAttr* attr, size_t size, uint32_t flags) {
  return static_cast<int>(syscall(SYS_landlock_create_ruleset, attr, size, flags));
}

// Grants `rights` beneath `path` (a file gets only the file rights among them); a path that
// does not exist is left out.
std::string allow(int ruleset, const std::string& path, uint64_t rights) {
  const int fd = open(path.c_str(), O_PATH | O_CLOEXEC);
  if (fd < 0) return errno == ENOENT ? "" : "landlock: cannot open " + path + ": " + std::strerror(errno);
  struct stat info {};
  fstat(fd, &info);
  landlock_path_beneath_attr rule{};
  rule.allowed_access = S_ISDIR(info.st_mode) ? rights : (rights & kFileRights);
  rule.parent_fd = fd;
  const long added = syscall(SYS_landlock_add_rule, ruleset, LANDLOCK_RULE_PATH_BENEATH, &rule, 0);
  const int error = errno;
  close(fd);
  return added == 0 ? "" : "landlock: cannot allow " + path + ": " + std::strerror(error);
}

}  // namespace

int landlock_abi() {
  const int abi = create_ruleset(nullptr, 0, LANDLOCK_CREATE_RULESET_VERSION);
  return abi < 0 ? 0 : abi;
}

std::string restrict_file_system(const ConfinementPaths& paths) {
  if (landlock_abi() < kNeededAbi)
    return "landlock: this kernel offers ABI " + std::to_string(landlock_abi()) + ", 6 is needed";
  const RulesetAttr attr{kAllRights, 0, kScopeAbstractUnix | kScopeSignal};
  const int ruleset = create_ruleset(&attr, sizeof attr, 0);
  if (ruleset < 0) return std::string("landlock: cannot create a ruleset: ") + std::strerror(errno);
  std::string problem;
  for (const std::string& path : paths.read_only) {
    if (problem.empty()) problem = allow(ruleset, path, kReadRights);
  }
  for (const std::string& path : paths.read_write) {
    if (problem.empty()) problem = allow(ruleset, path, kAllRights);
  }
  if (problem.empty() && syscall(SYS_landlock_restrict_self, ruleset, 0) != 0) {
    problem = std::string("landlock: cannot restrict: ") + std::strerror(errno);
  }
  close(ruleset);
  return problem;
}

}  // namespace stepdance::cli::confine
