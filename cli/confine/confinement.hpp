// Confinement of code from a page (docs/web.md, "What a sketch from a page may do"): Landlock
// for the file system and signals, seccomp for sockets and escapes, resource limits.
#pragma once

#include <stdint.h>

#include <string>
#include <vector>

namespace stepdance::cli::confine {

/// Resource limits of a confined process and of every process it starts (each its own CPU time).
struct ConfinementLimits {
  double cpu_s = 300;                  ///< CPU seconds (SIGXCPU, then SIGKILL 5 s later)
  uint64_t memory_bytes = 2ull << 30;  ///< address space (not set under AddressSanitizer)
  uint64_t file_bytes = 64ull << 20;   ///< largest file it may write (SIGXFSZ past it)
  uint64_t open_files = 256;           ///< file descriptors
};

/// The file system a confined process sees: everything else can be neither read nor written.
struct ConfinementPaths {
  std::vector<std::string> read_only;   ///< files or folders it may read and execute (beneath)
  std::vector<std::string> read_write;  ///< folders it may read, write, create and remove in
};

/// What this kernel lacks for confine_process(), one sentence per missing guard; empty when it
/// has them all (Landlock ABI 6 or later, seccomp filters). Context: any, no side effects.
std::vector<std::string> missing_guards();

/// Confines the calling process, from now on and irrevocably, with everything it starts later:
/// the limits, no capabilities, no new privileges, Landlock rules for `paths` (and no signals
/// to processes outside), and a seccomp filter refusing sockets, new sessions or process
/// groups, raising limits and io_uring. Returns "" or what could not be set (then the process
/// must not run what it was to run). Context: a single-threaded process, before it runs
/// untrusted code.
std::string confine_process(const ConfinementPaths& paths, const ConfinementLimits& limits);

/// The parts of confine_process(), each "" or what failed.
std::string set_resource_limits(const ConfinementLimits& limits);
std::string drop_privileges();
std::string restrict_file_system(const ConfinementPaths& paths);
std::string filter_system_calls();
/// The Landlock ABI this kernel offers (0: none).
int landlock_abi();

}  // namespace stepdance::cli::confine
