// Inside a WebAssembly board module: exit(), abort() and their kin, as the sketch sees them.
//
// The same contract as sketch_exit.cpp (the native one): these definitions take the place of the
// C library's for every call made from this board's code, the simulator hears how the sketch
// ended, and the board leaves the entry point it is in. Two things differ: musl declares these
// functions without noexcept, and outside every entry point (a global constructor) the module
// has no process to end, so it traps (the page's Worker reports the trap).
#include <cstdlib>

#include "board/abi/board_abi.h"
#include "board/runtime/entry_guard.hpp"
#include "stepdance/platform/sim/host_link.hpp"

namespace stepdance::sim_runtime {
namespace {

/// The code an entry returns after the sketch ended the program.
constexpr int kEscapeSketchEnded = 3;

[[noreturn]] void sketch_ended(int how, int status) {
  host().sketch_ended(host_context(), how, status);
  EntryGuard::escape(kEscapeSketchEnded);
  __builtin_trap();  // only reached outside every entry point
}

}  // namespace
}  // namespace stepdance::sim_runtime

extern "C" {
void exit(int status) { stepdance::sim_runtime::sketch_ended(STEPDANCE_END_EXIT, status); }
void _Exit(int status) { stepdance::sim_runtime::sketch_ended(STEPDANCE_END_QUICK_EXIT, status); }
void quick_exit(int status) { stepdance::sim_runtime::sketch_ended(STEPDANCE_END_QUICK_EXIT, status); }
void _exit(int status) { stepdance::sim_runtime::sketch_ended(STEPDANCE_END_QUICK_EXIT, status); }
void abort() { stepdance::sim_runtime::sketch_ended(STEPDANCE_END_ABORT, 0); }
}
