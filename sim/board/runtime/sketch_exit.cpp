// Inside a board's shared object: exit(), abort() and their kin, as the sketch sees them.
//
// A sketch that calls exit(0) must not end the simulator (a false pass) and one that calls
// abort() must not kill it: these definitions take the place of the C library's for every call
// made from this board's code (the shared object binds its own symbols first, and exports none
// of them). The simulator hears how the sketch ended, and the board leaves the entry point it is
// in. Outside every entry point (a global constructor) the host ends the process itself.
#include <sys/syscall.h>
#include <unistd.h>

#include <cstdlib>

#include "board/abi/board_abi.h"
#include "board/runtime/entry_guard.hpp"
#include "stepdance/platform/sim/host_link.hpp"

namespace stepdance::sim_runtime {
namespace {

/// The code an entry returns after the sketch ended the program.
constexpr int kEscapeSketchEnded = 3;

/// The process's exit status if the host cannot be told (the sketch ended the program from a
/// global constructor, before the board was attached): the simulator's "a sketch failed".
constexpr int kStatusSketchFailed = 5;

[[noreturn]] void sketch_ended(int how, int status) {
  host().sketch_ended(host_context(), how, status);
  EntryGuard::escape(kEscapeSketchEnded);
  // Only reached outside every entry point, where the host ends the process itself; the
  // detached stand-in (no host yet) has said why on stderr. This board's own exit() is the one
  // above, so the process ends with the system call.
  syscall(SYS_exit_group, kStatusSketchFailed);
  __builtin_unreachable();
}

}  // namespace
}  // namespace stepdance::sim_runtime

extern "C" {
void exit(int status) noexcept { stepdance::sim_runtime::sketch_ended(STEPDANCE_END_EXIT, status); }
void _Exit(int status) noexcept { stepdance::sim_runtime::sketch_ended(STEPDANCE_END_QUICK_EXIT, status); }
void quick_exit(int status) noexcept { stepdance::sim_runtime::sketch_ended(STEPDANCE_END_QUICK_EXIT, status); }
void _exit(int status) { stepdance::sim_runtime::sketch_ended(STEPDANCE_END_QUICK_EXIT, status); }
void abort() noexcept { stepdance::sim_runtime::sketch_ended(STEPDANCE_END_ABORT, 0); }
}
